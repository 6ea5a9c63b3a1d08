// Reading one DIC frame in the layouts of frame.h. One pass over the text, cells as string views
// (a frame holds 10^4 points and a test 300 frames: the reader is most of the time, see
// bench/bench_dic.cc), numbers by std::from_chars.
#include "fiberbridge/dic/frame.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <sstream>

namespace fiberbridge::dic {

namespace {

const char* const our_names[] = {"x", "y", "u", "v", "eyy", "valid", "time_s"};
static_assert(sizeof our_names / sizeof *our_names == n_frame_columns);
constexpr int cx = col_x, cy = col_y, cu = col_u, cv = col_v, ceyy = col_eyy, cvalid = col_valid,
              ctime = col_time, n_cols = n_frame_columns;

std::string_view trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r' || s[b] == '\n'))
    ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r' || s[e - 1] == '\n'))
    --e;
  return s.substr(b, e - b);
}

std::string_view unquote(std::string_view s) {
  s = trim(s);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"')
    s = trim(s.substr(1, s.size() - 2));
  return s;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (auto& c : out)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

/// The name before a unit in brackets ("epsy [%]" -> "epsy"), lower case.
std::string stem_of(std::string_view header) {
  const auto b = header.find('[');
  return lower(trim(b == std::string_view::npos ? header : header.substr(0, b)));
}

/// The unit in brackets of a header ("epsy [%]" -> "%"), empty without one.
std::string unit_of(std::string_view header) {
  const auto b = header.find('['), e = header.find(']');
  if (b == std::string_view::npos || e == std::string_view::npos || e < b)
    return "";
  return std::string(trim(header.substr(b + 1, e - b - 1)));
}

/// Splits a line into cells: ',' ';' '\t' as given, ' ' meaning runs of blanks.
void split(std::string_view line, char delim, std::vector<std::string_view>& cells) {
  cells.clear();
  if (delim == ' ') {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
        ++i;
      if (i >= line.size())
        break;
      const std::size_t b = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r')
        ++i;
      cells.push_back(line.substr(b, i - b));
    }
    return;
  }
  std::size_t b = 0;
  while (true) {
    const auto e = line.find(delim, b);
    cells.push_back(line.substr(b, e == std::string_view::npos ? std::string_view::npos : e - b));
    if (e == std::string_view::npos)
      return;
    b = e + 1;
  }
}

enum class Cell { number, missing, text };

/// Parses a cell: a finite number, a missing value (empty or NaN: a failed point), or text.
/// A decimal comma (German GOM exports, `;` delimited) is accepted.
Cell parse_number(std::string_view c, double& value) {
  c = unquote(c);
  if (c.empty()) {
    value = NAN;
    return Cell::missing;
  }
  if (c.front() == '+')
    c.remove_prefix(1);
  const auto r = std::from_chars(c.data(), c.data() + c.size(), value);
  if (r.ec == std::errc() && r.ptr == c.data() + c.size()) {
    if (std::isnan(value))
      return Cell::missing;
    return std::isfinite(value) ? Cell::number : Cell::text;
  }
  if (c.find(',') != std::string_view::npos && c.find('.') == std::string_view::npos) {
    std::string dot(c);
    std::replace(dot.begin(), dot.end(), ',', '.');
    const auto r2 = std::from_chars(dot.data(), dot.data() + dot.size(), value);
    if (r2.ec == std::errc() && r2.ptr == dot.data() + dot.size() && std::isfinite(value))
      return Cell::number;
  }
  if (r.ec == std::errc::result_out_of_range)
    return Cell::text;
  return Cell::text;
}

/// What a strain unit multiplies by: 0.01 for %, 1 for [1], [-] or none; -1 for anything else.
double strain_factor_of(const std::string& unit) {
  return unit == "%" ? 0.01 : unit == "1" || unit == "-" || unit.empty() ? 1.0 : -1;
}

/// A units cell ("[mm]", "mm", "%"): the unit without brackets.
std::string units_cell(std::string_view cell) {
  std::string_view u = unquote(cell);
  if (u.size() >= 2 && u.front() == '[' && u.back() == ']')
    u = trim(u.substr(1, u.size() - 2));
  return std::string(u);
}

std::string where(const std::string& source, std::size_t line) {
  return source + ":" + std::to_string(line);
}

/// A point given twice (the same reference x, y) with different displacements or strain: an
/// export of two overlapping areas of interest, or a damaged file. Which one is the material's is
/// not ours to guess, and taking either moved the tip by tens of mm (issue 42): refused. The same
/// point repeated with the same values is harmless and kept.
void refuse_conflicting_duplicates(const RawFrame& f, const std::vector<std::size_t>& lines) {
  std::vector<std::size_t> order;
  order.reserve(f.x.size());
  for (std::size_t i = 0; i < f.x.size(); ++i)
    if (f.valid[i] && std::isfinite(f.x[i]) && std::isfinite(f.y[i]))
      order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return f.x[a] < f.x[b] ||
           (f.x[a] == f.x[b] && (f.y[a] < f.y[b] || (f.y[a] == f.y[b] && a < b)));
  });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::size_t a = order[k - 1], b = order[k];
    if (f.x[a] != f.x[b] || f.y[a] != f.y[b])
      continue;
    if (f.u[a] == f.u[b] && f.v[a] == f.v[b] && f.eyy[a] == f.eyy[b])
      continue;
    const std::size_t la = std::min(lines[a], lines[b]), lb = std::max(lines[a], lines[b]);
    throw InputError(where(f.source, lb) + ": point (" + fmt(f.x[b]) + ", " + fmt(f.y[b]) +
                     ") is also on line " + std::to_string(la) + " with other values (eyy " +
                     fmt(f.eyy[lines[a] < lines[b] ? a : b]) + " there, " +
                     fmt(f.eyy[lines[a] < lines[b] ? b : a]) +
                     " here): a point given twice with different displacements or strain; "
                     "export one area of interest, or remove one of the two rows");
  }
}

} // namespace

FrameColumnMap FrameColumnMap::parse(const std::string& text, const std::string& where) {
  FrameColumnMap map;
  // Blanks as this file's trim: line ends too.
  for (const auto& item : split_list(text, ',', " \t\r\n")) {
    const std::string_view entry = item;
    const auto colon = entry.find(':');
    if (colon == std::string_view::npos)
      throw InputError(where + ": entry '" + std::string(entry) +
                       "' has no ':' (expected 'our_name: file header')");
    const std::string ours(trim(entry.substr(0, colon)));
    const std::string theirs(unquote(entry.substr(colon + 1)));
    if (std::find(std::begin(our_names), std::end(our_names), ours) == std::end(our_names))
      throw InputError(where + ": '" + ours +
                       "' is not one of our frame columns (x, y, u, v, eyy, valid, time_s)");
    if (theirs.empty())
      throw InputError(where + ": '" + ours + "' is mapped to an empty header");
    if (!map.file_header.emplace(ours, theirs).second)
      throw InputError(where + ": '" + ours + "' is mapped twice");
  }
  return map;
}

RawFrame read_frame(const std::string& path, const FrameReadOptions& options) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f)
    throw InputError(path + ": cannot open DIC frame for reading");
  std::string text;
  char buffer[1 << 16];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;)
    text.append(buffer, n);
  std::fclose(f);
  return parse_frame(text, path, options);
}

RawFrame parse_frame(std::string_view text, const std::string& source,
                     const FrameReadOptions& options) {
  RawFrame frame;
  frame.source = source;
  if (text.substr(0, 3) == "\xEF\xBB\xBF")
    text.remove_prefix(3);

  bool dice_banner = false;
  std::string comment_header; // the last '#' line that looks like a header (nodemaps)
  std::vector<std::string> header;
  bool quoted_header = false;
  char delim = ',';
  int index[n_cols];
  std::fill(std::begin(index), std::end(index), -1);
  std::vector<std::string_view> cells;
  std::size_t line_no = 0, pos = 0;
  std::string header_line_text;

  // Sets the header from a line, detects the delimiter, the layout and the columns.
  const auto take_header = [&](std::string_view line, std::size_t at) {
    header_line_text = std::string(trim(line));
    delim = line.find(';') != std::string_view::npos    ? ';'
            : line.find(',') != std::string_view::npos  ? ','
            : line.find('\t') != std::string_view::npos ? '\t'
                                                        : ' ';
    split(line, delim, cells);
    for (const auto c : cells) {
      const auto t = trim(c);
      quoted_header = quoted_header || (!t.empty() && t.front() == '"');
      header.emplace_back(unquote(c));
    }
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i].empty())
        throw InputError(where(source, at) + ": header column " + std::to_string(i + 1) +
                         " has no name");
    Layout layout = options.layout;
    if (layout == Layout::automatic) {
      // The surest layout the header is (layouts.h: each entry's detect); plain otherwise.
      const HeaderFacts facts{header, delim, dice_banner, quoted_header};
      int best = 0;
      layout = Layout::plain;
      for (const auto* e : layouts())
        if (const int score = e->detect(facts); score > best) {
          best = score;
          layout = e->id;
        }
    }
    const LayoutEntry& entry = layout_entry(layout);
    frame.layout = layout;
    for (int col = 0; col < n_cols; ++col) {
      const auto mapped = options.columns.file_header.find(our_names[col]);
      std::vector<std::string> candidates = mapped != options.columns.file_header.end()
                                                ? std::vector<std::string>{mapped->second}
                                                : entry.preset(col, options.pixel_coordinates);
      const bool by_stem = entry.by_stem && mapped == options.columns.file_header.end();
      for (const auto& want : candidates) {
        for (std::size_t i = 0; i < header.size() && index[col] < 0; ++i)
          if (by_stem ? stem_of(header[i]) == want : header[i] == want)
            index[col] = static_cast<int>(i);
        // A unit after the name ("X [mm]", "eyy [1]", as some VIC versions write): the name
        // before it, case kept (VIC's x is pixels, X millimetres).
        for (std::size_t i = 0; i < header.size() && index[col] < 0; ++i)
          if (!by_stem && mapped == options.columns.file_header.end() &&
              header[i].find('[') != std::string::npos &&
              trim(std::string_view(header[i]).substr(0, header[i].find('['))) == want)
            index[col] = static_cast<int>(i);
        if (index[col] >= 0)
          break;
      }
      const bool required = col <= ceyy;
      if (index[col] < 0 && (required || mapped != options.columns.file_header.end())) {
        std::string have;
        for (const auto& h : header)
          have += (have.empty() ? "" : ", ") + h;
        std::string hint;
        throw InputError(where(source, at) + ": missing column '" +
                         (candidates.empty() ? std::string(our_names[col]) : candidates.front()) +
                         "' for " + our_names[col] + " (" + layout_name(layout) +
                         " layout; columns present: " + have + ")" + hint +
                         "; map it with the frame Columns");
      }
      if (index[col] >= 0)
        frame.used[our_names[col]] = header[index[col]];
    }
    const std::string unit = unit_of(header[index[ceyy]]);
    frame.strain_factor = strain_factor_of(unit);
    if (unit.empty() && entry.percent_strains)
      frame.strain_factor = 0.01; // GOM writes strains in percent
    if (frame.strain_factor < 0)
      throw InputError(where(source, at) + ": strain column '" + header[index[ceyy]] +
                       "' has unit [" + unit + "]; expected [%], [1] or none");
  };

  double values[n_cols];
  bool valid_is_flag = false;
  // GOM Correlate / ZEISS Inspect native CSV: a `stage;index;relative_time;date` line and its one
  // value row above the point table, and a units line under the point table's header.
  std::vector<std::string> stage_names;
  bool stage_values_read = false, after_header = false;
  std::vector<std::size_t> row_lines; // the file line of each point (duplicates are named by it)
  while (pos < text.size()) {
    auto end = text.find('\n', pos);
    if (end == std::string_view::npos)
      end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    const std::string_view content = trim(line);
    if (content.empty())
      continue; // blank lines separate VIC's areas of interest
    if (content.substr(0, 3) == "***") {
      dice_banner = true;
      // DICe states its coordinates in the comment block ("*** Coordinates: px, y down"): the
      // analysis takes them from here rather than from an option the user may not know to give.
      const std::string l = lower(content);
      const auto c = l.find("coordinates");
      if (c != std::string::npos && frame.stated_coordinates.empty()) {
        const std::string rest = l.substr(c + 11);
        // DICe 2D writes image coordinates ("(0,0) as upper left corner of image"): pixels.
        const bool px = rest.find("px") != std::string::npos ||
                        rest.find("pixel") != std::string::npos ||
                        rest.find("image") != std::string::npos;
        const bool mm = rest.find("mm") != std::string::npos;
        if (px != mm) {
          frame.stated_coordinates = px ? "px" : "mm";
          frame.stated_line = line_no;
        }
      }
      continue;
    }
    if (content.front() == '#') {
      if (header.empty()) {
        std::string_view h = content;
        while (!h.empty() && h.front() == '#')
          h.remove_prefix(1);
        if (h.find(';') != std::string_view::npos || h.find(',') != std::string_view::npos)
          comment_header = std::string(trim(h));
      }
      continue;
    }
    if (header.empty() &&
        (!stage_names.empty() ||
         lower(unquote(content.substr(0, content.find_first_of(";,\t")))) == "stage")) {
      split(content, content.find(';') != std::string_view::npos ? ';' : ',', cells);
      if (stage_names.empty()) {
        for (const auto c : cells)
          stage_names.emplace_back(lower(unquote(c)));
        continue;
      }
      if (!stage_values_read) {
        stage_values_read = true;
        if (cells.size() != stage_names.size())
          throw InputError(where(source, line_no) + ": the stage line above names " +
                           std::to_string(stage_names.size()) + " values, this row has " +
                           std::to_string(cells.size()) + " (GOM stage block)");
        for (std::size_t i = 0; i < cells.size(); ++i) {
          double t;
          if (stage_names[i] == "relative_time" && parse_number(cells[i], t) == Cell::number)
            frame.stage_time = t;
        }
        continue;
      }
      stage_names.clear(); // the stage block is over: this line is the point table's header
    }
    if (header.empty()) {
      split(content, content.find(';') != std::string_view::npos ? ';' : ',', cells);
      double probe;
      if (parse_number(cells.front(), probe) == Cell::number) {
        if (comment_header.empty())
          throw InputError(where(source, line_no) +
                           ": data before any header line (expected column names first)");
        take_header(comment_header, line_no);
      } else {
        take_header(content, line_no);
        valid_is_flag = index[cvalid] >= 0 && lower(header[index[cvalid]]) == "valid";
        after_header = true;
        continue;
      }
      valid_is_flag = index[cvalid] >= 0 && lower(header[index[cvalid]]) == "valid";
    }
    split(content, delim, cells);
    if (after_header) {
      after_header = false;
      // A units line under the header (GOM native: ";mm;mm;...;%"): no number in it.
      bool units_line = cells.size() == header.size();
      bool some_text = false;
      for (std::size_t i = 0; units_line && i < cells.size(); ++i) {
        double probe;
        const auto kind = parse_number(cells[i], probe);
        units_line = kind != Cell::number;
        some_text = some_text || kind == Cell::text;
      }
      if (units_line && some_text) {
        const std::string unit = units_cell(cells[index[ceyy]]);
        const double factor = strain_factor_of(unit);
        if (factor < 0)
          throw InputError(where(source, line_no) + ": strain column '" + header[index[ceyy]] +
                           "' has unit '" + unit + "' in the units line; expected %, 1 or none");
        if (!unit.empty() || unit_of(header[index[ceyy]]).empty())
          frame.strain_factor =
              unit.empty() && layout_entry(frame.layout).percent_strains ? 0.01 : factor;
        continue;
      }
    }
    if (cells.size() != header.size()) {
      if (content == header_line_text)
        continue; // a header repeated before the next area of interest
      throw InputError(where(source, line_no) + ": expected " + std::to_string(header.size()) +
                       " values as the header has, found " + std::to_string(cells.size()));
    }
    bool failed = false;
    for (int col = 0; col < n_cols; ++col) {
      values[col] = NAN;
      if (index[col] < 0)
        continue;
      const auto kind = parse_number(cells[index[col]], values[col]);
      if (kind == Cell::text)
        throw InputError(where(source, line_no) + ": column '" + header[index[col]] + "' holds '" +
                         std::string(trim(cells[index[col]])) + "', expected a finite number");
      if (kind == Cell::missing && col <= ceyy)
        failed = true;
    }
    // A confidence column (VIC's sigma, DICe's SIGMA) marks a failed point by a negative value;
    // a flag column named valid also by 0.
    if (index[cvalid] >= 0 && (values[cvalid] < 0 || (valid_is_flag && values[cvalid] == 0)))
      failed = true;
    if (std::isnan(frame.time) && !std::isnan(values[ctime]))
      frame.time = values[ctime];
    frame.x.push_back(values[cx]);
    frame.y.push_back(values[cy]);
    frame.u.push_back(values[cu]);
    frame.v.push_back(values[cv]);
    frame.eyy.push_back(values[ceyy] * frame.strain_factor);
    frame.valid.push_back(failed ? 0 : 1);
    frame.n_failed += failed;
    row_lines.push_back(line_no);
  }
  if (std::isnan(frame.time) && !std::isnan(frame.stage_time))
    frame.time = frame.stage_time;
  if (header.empty())
    throw InputError(source + ": no header line with column names (empty DIC frame?)");
  if (frame.x.empty())
    throw InputError(source + ": header found but no data rows");
  refuse_conflicting_duplicates(frame, row_lines);
  return frame;
}

} // namespace fiberbridge::dic
