"""fiberbridge from Python: the same chain as the scenes and the command line, numpy arrays in
and out.

    import fiberbridge as fb
    red = fb.reduce(["DCB-01.csv"], width_mm=20, height_mm=20, columns={"load_N": "Load"})
    ext = fb.extract("rdelta.csv")                # or fb.extract(red) when delta_root was measured
    fit = fb.fit_trilinear(ext)
    sim = fb.simulate(fit, model="beam")          # the fitted law back in the seed's specimen
    summary = fb.run_scene("prm/default.prm", set={"MPM/Tip advance": 10})

Every keyword with a unit carries it in its name, as the CSV columns do (width_mm, E_L_MPa,
delta_c_mm). Any key of a scene section can also be given as settings={"Section/Key": value};
the values are read by the scene reader, so they mean what they mean in a .prm file. Bad input
raises fb.InputError (a ValueError) with the command line's one-line message; a computation that
cannot resolve its case raises fb.ComputationError. Results have .to_dict() and a short repr;
their arrays are numpy arrays in the units their names say. The C++ work runs without the GIL.
"""
import numpy as np

from . import _core

InputError = _core.InputError
ComputationError = _core.ComputationError

__all__ = ["InputError", "ComputationError", "read_record", "read_records", "reduce", "dic",
           "extract", "fit_trilinear", "campaign", "simulate", "identify", "run_scene", "Result"]

# Keyword arguments with units -> scene keys (the units are those of the .prm sections).
_SPECIMEN = {"width_mm": "Specimen/Width", "height_mm": "Specimen/Height",
             "length_mm": "Specimen/Length", "initial_crack_mm": "Specimen/Initial crack"}
_MATERIAL = {"E_L_MPa": "Material/E_L", "E_T_MPa": "Material/E_T", "G_LT_MPa": "Material/G_LT",
             "nu_LT": "Material/nu_LT", "density_kg_m3": "Material/Density",
             "plane": "Material/Plane"}
_TEST = {"encoding": "Test/Encoding", "crack_length": "Test/Crack length",
         "smoothing_window_mm": "Test/Smoothing window",
         "plateau_fraction": "Test/Plateau fraction",
         "large_displacement_correction": "Test/Large displacement correction",
         "use_specimen_initial_crack": "Test/Use specimen initial crack"}


def _value(v):
    """A Python value as the text a .prm file would hold."""
    if hasattr(v, "dtype") and hasattr(v, "item") and getattr(v, "ndim", 1) == 0:
        v = v.item()  # a numpy scalar (np.float64, np.bool_, ...) as the Python number it holds
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, (list, tuple)):
        return ", ".join(_value(x) for x in v)
    return str(v)


def _settings(where, kwargs, tables, settings):
    """kwargs (by the tables) and settings={"Section/Key": value} as "Section/Key=value" lines."""
    out = []
    for name, value in kwargs.items():
        if value is None:
            continue
        for table in tables:
            if name in table:
                out.append(table[name] + "=" + _value(value))
                break
        else:
            known = sorted(k for t in tables for k in t)
            raise TypeError(f"{where}() got an unexpected keyword argument '{name}'; "
                            f"expected one of {', '.join(known)} or settings={{'Section/Key': value}}")
    for key, value in (settings or {}).items():
        out.append(f"{key}={_value(value)}")
    return out


def _columns(columns):
    """{'load_N': 'Load', ...} as Test/Columns' text (our name: the file's header or '#3')."""
    if columns is None:
        return []
    if isinstance(columns, str):
        return ["Test/Columns=" + columns]
    return ["Test/Columns=" + ", ".join(f"{ours}: {theirs}" for ours, theirs in columns.items())]


class Result:
    """A result: its fields as attributes, .to_dict(), and a repr of its scalars."""

    _kind = "Result"

    def __init__(self, fields):
        self.__dict__.update(fields)

    def to_dict(self):
        def plain(v):
            if isinstance(v, Result):
                return v.to_dict()
            if isinstance(v, list):
                return [plain(x) for x in v]
            if isinstance(v, dict):
                return {k: plain(x) for k, x in v.items()}
            return v
        return {k: plain(v) for k, v in self.__dict__.items() if not k.startswith("_")}

    def __repr__(self):
        parts, arrays = [], {}
        for k, v in self.__dict__.items():
            if k.startswith("_"):
                continue
            if isinstance(v, float):
                parts.append(f"{k}={v:.6g}")
            elif isinstance(v, (int, bool)) or (isinstance(v, str) and len(v) < 40):
                parts.append(f"{k}={v!r}")
            elif hasattr(v, "shape"):
                arrays.setdefault(v.shape[0], []).append(k)
        for n, names in arrays.items():
            parts.append(f"arrays of {n}: {' '.join(names)}")
        return f"{self._kind}({', '.join(parts)})"


class Record(Result):
    _kind = "Record"


class ReducedRecord(Result):
    _kind = "ReducedRecord"


class Reduction(Result):
    """reduce's result: .records (one ReducedRecord each), .mean, .summary (summary.json's
    reduce block)."""
    _kind = "Reduction"

    def __repr__(self):
        names = ", ".join(r.name for r in self.records)
        return f"Reduction({len(self.records)} records: {names})"


class DicResult(Result):
    """dic's result: the test record's columns (time_s, opening_mm, load_N, a_mm,
    delta_root_mm, their _sd_mm), and per frame read: frame_time_s, frame_tip_mm, frame_used,
    frame_notes."""
    _kind = "DicResult"


class Extraction(Result):
    _kind = "Extraction"


class TrilinearFit(Result):
    _kind = "TrilinearFit"


class Simulation(Result):
    _kind = "Simulation"


class Identification(Result):
    """identify's result: the trilinear law's fields, .estimates {name: (value, std_error)},
    .records (each record's fit), the band, .notes, and .law (a TrilinearFit for simulate)."""
    _kind = "Identification"


def read_records(path, columns=None, settings=None, **kwargs):
    """Every record of one file (a file may hold several, by its `record` column), read as a
    scene's reduce reads Test/Files: columns={'load_N': 'Load', 'opening_mm': '#2'}, encoding,
    crack_length ('auto', 'measured', 'equivalent'), any Test key in settings."""
    s = _columns(columns) + _settings("read_records", kwargs, [_TEST], settings)
    return [Record(r) for r in _core.read_records(str(path), s)]


def read_record(path, columns=None, settings=None, **kwargs):
    """The one record of a file (InputError when it holds several: use read_records)."""
    records = read_records(path, columns, settings, **kwargs)
    if len(records) != 1:
        raise InputError(f"{path}: holds {len(records)} records "
                         f"({', '.join(r.name for r in records)}); use fb.read_records")
    return records[0]


_RECORD_COLUMNS = ("time_s", "opening_mm", "load_N", "a_mm", "delta_root_mm")


def _record_items(where, records):
    """The records of a call as _core takes them: a path as str, a record in memory as a dict of
    its name, source and columns. A record in memory is a Record (read_record's), a DicResult, or
    a mapping of columns (a dict of arrays, a pandas DataFrame) with opening_mm and load_N,
    optionally time_s, a_mm, delta_root_mm and name."""
    if isinstance(records, (str, bytes)) or hasattr(records, "__fspath__") or \
            isinstance(records, Result) or hasattr(records, "keys"):
        records = [records]
    items = []
    for k, r in enumerate(records):
        if isinstance(r, (str, bytes)) or hasattr(r, "__fspath__"):
            items.append(str(r) if not isinstance(r, bytes) else r.decode())
            continue
        if isinstance(r, (Record, DicResult)):
            data = {c: getattr(r, c) for c in _RECORD_COLUMNS if hasattr(r, c)}
            name = getattr(r, "name", None)
        elif isinstance(r, Result):
            # A reduction's record holds one row per crack reading, not the test's rows.
            raise TypeError(f"fiberbridge.{where}: records[{k}] is a {r._kind}; expected a path, "
                            "a Record (fb.read_record), a DicResult (fb.dic) or a mapping of "
                            "columns")
        elif hasattr(r, "keys"):
            keys = set(r.keys())
            unknown = keys - set(_RECORD_COLUMNS) - {"name"}
            if unknown:
                raise InputError(f"fiberbridge.{where}: records[{k}] has unknown column(s) "
                                 f"{', '.join(sorted(map(str, unknown)))}; expected "
                                 f"{', '.join(_RECORD_COLUMNS)} (opening_mm and load_N required) "
                                 "and optionally name")
            data = {c: r[c] for c in _RECORD_COLUMNS if c in keys}
            name = r["name"] if "name" in keys and isinstance(r["name"], str) else None
        else:
            raise TypeError(f"fiberbridge.{where}: records[{k}] is a {type(r).__name__}; expected "
                            "a path, a Record (fb.read_record), a DicResult (fb.dic) or a "
                            "mapping of columns")
        missing = [c for c in ("opening_mm", "load_N") if c not in data]
        if missing:
            raise InputError(f"fiberbridge.{where}: records[{k}] has no {' or '.join(missing)}; "
                             "a record needs opening_mm and load_N")
        name = name or f"record{k + 1}"
        item = {"name": name,
                "source": f"fiberbridge.{where}: records[{k}] '{name}' (arrays; line n is row n, "
                          "from 1)"}
        for c, v in data.items():
            # A column of no values (read_record's for a column the file lacks) is no column.
            if v is None or np.size(v) == 0:
                item[c] = None
                continue
            try:
                item[c] = np.asarray(v, dtype=float).ravel()
            except (TypeError, ValueError) as e:
                raise InputError(f"fiberbridge.{where}: records[{k}] '{name}': column {c} is not "
                                 f"numbers ({e})") from None
        items.append(item)
    return items


def reduce(records, columns=None, settings=None, progress=None, **kwargs):
    """R(a) of the records by direct energy, MBT, CC, MCC and CBBM, their initiation and plateau
    values and mean, as a scene's reduce computes them. `records`: one or several, each a file
    path, a Record (fb.read_record's, its arrays edited or not), a DicResult (fb.dic's) or a
    mapping of columns in memory (a dict of numpy arrays, a pandas DataFrame: opening_mm, load_N,
    optionally time_s, a_mm, delta_root_mm, name), cleaned as the reader cleans a file's rows.
    The specimen: width_mm, height_mm (both arms), length_mm, initial_crack_mm; the material:
    E_L_MPa, ...; the reading: columns, encoding, crack_length, smoothing_window_mm, ...
    progress(line) gets a line per record; Ctrl-C stops the call there. Nothing is written.
    Arrays in J/m^2 and N are read-only views of the result (copy to change them)."""
    items = _record_items("reduce", records)
    s = _columns(columns) + _settings("reduce", kwargs, [_SPECIMEN, _MATERIAL, _TEST], settings)
    r = _core.reduce(items, s, progress)
    out = Reduction({"records": [ReducedRecord(x) for x in r["records"]],
                     "mean": Result(r["mean"]), "summary": r["summary"],
                     "compute_s": r["compute_s"]})
    out._outcome = r["outcome"]
    out._settings = s  # the chain's settings, for fit_trilinear's correction by simulation
    return out


def dic(frames, machine_record, initial_crack_mm=None, columns=None, settings=None, **kwargs):
    """The paper's DIC step: the crack tip by the 1 % strain rule and the notch-root opening by a
    virtual extensometer on every frame, matched by time to the machine record, as a scene's dic
    finds them. `frames`: a glob or a list of files; the DIC section's keys in settings
    ({"DIC/Format": "vic", "DIC/Notch root x": 100, ...}); the machine record's columns as
    read_record's. Writes nothing (a scene's dic also writes dic_record.csv)."""
    if not isinstance(frames, str):
        frames = ", ".join(str(f) for f in frames)
    kw = dict(kwargs)
    kw["initial_crack_mm"] = initial_crack_mm
    s = ([f"DIC/Frames={frames}", f"Test/Files={machine_record}"] + _columns(columns) +
         _settings("dic", kw, [_SPECIMEN, _MATERIAL, _TEST], settings))
    return DicResult(_core.dic(s))


def _rdelta_columns(data):
    """(delta_mm, R_J_m2, a_mm, time_s, replicate) of a mapping of columns."""
    keys = set(data.keys())
    missing = [k for k in ("delta_mm", "R_J_m2") if k not in keys]
    if missing:
        raise InputError("fiberbridge.extract: the columns need delta_mm and R_J_m2 (optionally "
                         "a_mm, time_s, replicate); missing " + ", ".join(missing))
    unknown = keys - {"delta_mm", "R_J_m2", "a_mm", "time_s", "replicate"}
    if unknown:
        raise InputError("fiberbridge.extract: unknown column(s) " + ", ".join(sorted(unknown)) +
                         "; expected delta_mm, R_J_m2, a_mm, time_s, replicate")

    def numbers(k):
        return np.asarray(data[k], dtype=float).ravel() if k in keys else np.empty(0)
    labels = [str(v) for v in np.asarray(data["replicate"]).ravel()] if "replicate" in keys else []
    return numbers("delta_mm"), numbers("R_J_m2"), numbers("a_mm"), numbers("time_s"), labels


def extract(data, delta_c_mm="auto", j_tip="auto", intervals=None, smoothing=None,
            settings=None):
    """The bridging law by the paper's Eq. 5/6 beside the old sigma = dR/ddelta, with the steady
    state (J_tip, G_ss, delta_c). `data`: an R(delta) CSV (as `fiberbridge extract` reads it), a
    Reduction whose records all measured delta_root_mm, or columns in memory: a mapping (a dict of
    numpy arrays, a pandas DataFrame) with delta_mm and R_J_m2, optionally a_mm, time_s and
    replicate, checked as the file's columns are."""
    s = [f"Data/Delta c={_value(delta_c_mm)}", f"Data/J tip={_value(j_tip)}"]
    if intervals is not None:
        s.append(f"Data/Intervals={intervals}")
    if smoothing is not None:
        s.append(f"Data/Smoothing half-width={smoothing}")
    s += _settings("extract", {}, [], settings)
    if isinstance(data, Reduction):
        e = _core.extract_reduced(data._outcome, s)
    elif hasattr(data, "keys"):
        e = _core.extract_columns(*_rdelta_columns(data), s)
    else:
        e = _core.extract_file([f"Data/File={data}"] + s)
    outcome = e.pop("outcome")
    out = Extraction(e)
    out._outcome = outcome
    # From a Reduction, fit_trilinear can correct the law by simulating its records.
    out._reduction = data if isinstance(data, Reduction) else None
    out._settings = (data._settings if isinstance(data, Reduction) else []) + s
    return out


def fit_trilinear(extraction, delta1_mm=None, delta2_mm=None, free_breakpoints=None,
                  model_correction="auto", settings=None):
    """The trilinear fit of the Eq. 6 law (area G_ss - J_tip), breakpoints fixed (the paper's 0.1
    and 1 mm by default) or free. model_correction ("auto", "none", "beam"), as a scene's
    Fit/Model correction: when the extraction came from a Reduction, the law is corrected by
    simulation (the beam runs the records with it until the same chain gives back what it gave on
    them); .correction holds the outcome and, when it converged, the corrected law, which
    simulate() then uses as a scene's fit hands it on. The fields stay the seed's fit."""
    kw = {"delta1_mm": delta1_mm, "delta2_mm": delta2_mm, "free_breakpoints": free_breakpoints,
          "model_correction": model_correction}
    table = {"delta1_mm": "Fit/Delta 1", "delta2_mm": "Fit/Delta 2",
             "free_breakpoints": "Fit/Free breakpoints",
             "model_correction": "Fit/Model correction"}
    s = _settings("fit_trilinear", kw, [table], settings)
    fields = _core.fit_trilinear(extraction._outcome, s)
    law_si = fields.pop("law_si")
    reduction = getattr(extraction, "_reduction", None)
    correction = None
    if model_correction == "beam" and (reduction is None or not hasattr(_core, "correct_fit")):
        raise InputError("fiberbridge.fit_trilinear: model_correction='beam' needs an extraction "
                         "from a Reduction (its records are simulated) and a build with identify")
    if model_correction != "none" and reduction is not None and hasattr(_core, "correct_fit"):
        correction = _core.correct_fit(extraction._outcome, reduction._outcome, law_si,
                                       extraction._settings + s)
    fields["correction"] = correction
    out = TrilinearFit(fields)
    out._law_si = law_si
    out._j_tip = fields["J_tip_J_m2"]
    if correction is not None and correction["converged"]:
        out._law_si = correction.pop("law_si")
        out._j_tip = correction["J_tip_J_m2"]
    return out


class Campaign(Result):
    """campaign's result: summary.json's campaign block. .groups (one dict per material and
    cycles: trilinear, J1_J_m2, ..., ci with each quantity's interval, notes), .degradation,
    .ranking (most durable first), .ranking_confidence, .notes."""
    _kind = "Campaign"

    def __repr__(self):
        ok = sum(1 for g in self.groups if g["ok"])
        return (f"Campaign({self.n_specimens} specimens, {ok}/{self.n_groups} groups estimated, "
                f"ranking {' > '.join(self.ranking)})")


def campaign(manifest, settings=None, progress=None, **kwargs):
    """A durability campaign (the manifest CSV of specimens: material, cycles, their record or
    R(delta) file or DIC set) reduced to Table 1 with intervals from the replicates, the
    degradation per property and the ranking with its confidence, as a scene's campaign computes
    it. The Campaign section's keys in settings ({"Campaign/Interval": "percentile"}), the
    records' reading and specimen as in reduce. Writes nothing. progress(line) gets a line per
    group (and per simulation); Ctrl-C stops the call at the next one with KeyboardInterrupt."""
    s = ([f"Campaign/Manifest={manifest}"] +
         _settings("campaign", kwargs, [_SPECIMEN, _MATERIAL, _TEST], settings))
    return Campaign(_core.campaign(s, progress))


def simulate(law=None, model="beam", j_tip_J_m2=None, settings=None, progress=None, **kwargs):
    """One model's R curve (model 'beam', 'fem' or 'mpm') with `law` on the specimen of the
    keywords (width_mm, height_mm, length_mm, initial_crack_mm, E_L_MPa, ...) and the model's
    section in settings={'FEM/Element size': 1.0}. `law`: a TrilinearFit (with its J_tip unless
    j_tip_J_m2 is given) or None for the Cohesive law section of settings (the seed's PVA law by
    default). Writes nothing.

    progress: called with each of the model's progress lines (a str), as the command line prints
    them (the FEM every 10 tip advances). Ctrl-C is seen at those lines and stops the run with
    KeyboardInterrupt; an exception raised by progress stops it too."""
    s = _settings("simulate", kwargs, [_SPECIMEN, _MATERIAL], settings)
    tri = None
    if law is not None:
        if not isinstance(law, TrilinearFit):
            raise TypeError("simulate(law=...) takes a TrilinearFit, or None for the Cohesive "
                            "law section of settings")
        tri = law._law_si
        if j_tip_J_m2 is None:
            j_tip_J_m2 = getattr(law, "_j_tip", law.J_tip_J_m2)
    return Simulation(_core.simulate(model, s, tri, j_tip_J_m2, progress))


def identify(records, columns=None, settings=None, progress=None, **kwargs):
    """The law from load, opening and crack readings alone (no delta_root): identify's joint fit
    of the records with the Identify section (settings={"Identify/Starts": 1, ...}), as a scene's
    identify fits them, on this process. `records` as reduce takes them (paths, Records,
    DicResults, mappings of columns). The specimen and material as reduce takes them. Returns the
    trilinear law (delta1_mm, sigma1_kPa, ..., J_tip_J_m2), its estimates with standard errors,
    each record's fit (records[k]: model_load_N against load_N, ...), the law's band and the
    notes; .law is a TrilinearFit for simulate. progress: as simulate's (the fit's progress
    lines; Ctrl-C is seen there). Nothing is written."""
    items = _record_items("identify", records)
    s = (_columns(columns) +
         _settings("identify", kwargs, [_SPECIMEN, _MATERIAL, _TEST], settings))
    fields = _core.identify(items, s, progress)
    law_si = fields.pop("law_si")
    fields["records"] = [Result(r) for r in fields["records"]]
    out = Identification(fields)
    law = TrilinearFit({k: fields[k] for k in ("delta1_mm", "sigma1_kPa", "delta2_mm",
                                                 "sigma2_kPa", "delta_c_mm", "J_tip_J_m2")})
    law._law_si = law_si
    out.law = law
    return out


def run_scene(path, set=None, resume=False, progress=None):
    """Runs a .prm scene as `fiberbridge run` does (its files in its Output directory) and returns
    its summary.json as a dict. set={'Section/Key': value} as --set. progress(line) gets the run's
    progress lines (default: printed to stderr, as the command line prints them). Ctrl-C stops
    the run at its next progress line: KeyboardInterrupt, and the output directory keeps its
    marker of an incomplete run (no summary.json)."""
    s = [f"{k}={_value(v)}" for k, v in (set or {}).items()]
    return _core.run_scene(str(path), s, resume, progress)
