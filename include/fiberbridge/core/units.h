#pragma once
// SI inside the code; files and scenes speak mm, kPa, MPa. These are the only conversion factors.
namespace fiberbridge::units {
inline constexpr double mm = 1e-3;  ///< metres per millimetre
inline constexpr double um = 1e-6;  ///< metres per micrometre
inline constexpr double kPa = 1e3;  ///< pascals per kilopascal
inline constexpr double MPa = 1e6;  ///< pascals per megapascal
inline constexpr double GPa = 1e9;  ///< pascals per gigapascal
inline constexpr double mm2 = 1e-6; ///< square metres per square millimetre
} // namespace fiberbridge::units
