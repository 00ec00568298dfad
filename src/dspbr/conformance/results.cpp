#include "dspbr/conformance/results.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>

#include "dspbr/conformance/vector_file.h"
#include "dspbr/io/decimal.h"
#include "dspbr/io/json_fields.h"
#include "dspbr/io/message.h"
#include "dspbr/io/read_file.h"
#include "dspbr/limits.h"

namespace dspbr::conformance {

namespace {

using Json = nlohmann::json;
namespace jf = json_fields;

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw std::runtime_error(path + ": " + what); }


std::vector<Result> parse_json_results(std::string_view bytes, const std::string& path) {
  const Json doc = parse_json(bytes, path, "conformance results file");
  std::vector<Result> out;
  try {
    const Json& arr = jf::array_member(doc, "results", "");
    for (const auto& [key, value] : doc.items())  // a misspelt member would be silently dropped
      if (key != "results")
        throw std::runtime_error("unknown member " + in_quotes(key) + " (a results file holds only \"results\")");
    for (std::size_t i = 0; i < arr.size(); ++i) {
      const std::string where = jf::index_path("results", i);
      Result r;
      r.id = jf::string_member(arr[i], "id", where);
      const std::string w = where + " (id " + in_quotes(r.id) + ")";
      for (const auto& [key, value] : arr[i].items())
        if (key != "id" && key != "f_cos" && key != "pdf" && key != "albedo" && key != "emission" && key != "delta")
          throw std::runtime_error(w + ": unknown member " + in_quotes(key) +
                                   " (known: id, f_cos, pdf, albedo, emission, delta)");
      // A member left out or null: not supplied (not judged).
      const auto supplied = [&](const char* key) { return arr[i].contains(key) && !arr[i][key].is_null(); };
      if (supplied("f_cos")) r.f_cos = read_rgb(arr[i], "f_cos", w);
      if (supplied("pdf")) r.pdf = jf::number_member(arr[i], "pdf", w);
      if (supplied("albedo")) r.albedo = read_rgb(arr[i], "albedo", w);
      if (supplied("emission")) r.emission = read_rgb(arr[i], "emission", w);
      if (supplied("delta")) {
        const Json& d = jf::array_member(arr[i], "delta", w);
        std::vector<DeltaExpectation> lobes;
        for (std::size_t k = 0; k < d.size(); ++k) {
          const std::string wk = jf::index_path(jf::member_path(w, "delta"), k);
          const Rgb l = read_rgb(d[k], "l", wk);
          // A direction computed in float: unit within 1e-3 (the lobes are matched by direction).
          const double length = std::sqrt(l.r * l.r + l.g * l.g + l.b * l.b);
          if (!(std::abs(length - 1) <= 1e-3))
            throw std::runtime_error(jf::member_path(wk, "l") + " must be a unit vector (length 1 within 1e-3), got length " +
                                     jf::excerpt(Json(length)));
          lobes.push_back({Vec3{l.r, l.g, l.b}, read_rgb(d[k], "value", wk)});
        }
        r.delta = std::move(lobes);
      }
      out.push_back(std::move(r));
    }
  } catch (const std::runtime_error& e) {
    fail(path, e.what());
  }
  return out;
}

// The fields of one CSV line (RFC 4180 quoting: a quoted field may hold commas and doubled quotes),
// at most `max_fields` of them: a line with more is refused ("WHERE: more than N fields" and `why`)
// when the field after the last is reached (a line of 15 MB of commas would otherwise be 7.5
// million strings, 40 x its size).
std::vector<std::string> csv_fields(std::string_view line, const std::string& where, std::size_t max_fields,
                                    const std::string& why) {
  std::vector<std::string> out;
  std::string cur;
  std::size_t i = 0;
  while (true) {
    cur.clear();
    if (i < line.size() && line[i] == '"') {
      ++i;
      while (true) {
        if (i >= line.size()) throw std::runtime_error(where + ": unterminated quoted field");
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') cur += '"', i += 2;
          else { ++i; break; }
        } else {
          cur += line[i++];
        }
      }
      if (i < line.size() && line[i] != ',') throw std::runtime_error(where + ": text after a quoted field");
    } else {
      while (i < line.size() && line[i] != ',') cur += line[i++];
    }
    if (out.size() == max_fields)
      throw std::runtime_error(where + ": more than " + std::to_string(max_fields) + " fields" + why);
    out.push_back(cur);
    if (i >= line.size()) break;
    ++i;  // the comma
  }
  return out;
}

double csv_number(const std::string& text, const std::string& column, const std::string& where) {
  const Decimal x = parse_decimal(text);  // the one number grammar (decimal.h)
  if (x.status != Decimal::Ok)
    throw std::runtime_error(where + ": " + column + " is not a finite decimal number: " + in_quotes(text));
  return x.value;
}

// Three fields NAME_r, NAME_g, NAME_b from f[c]: all empty is not supplied.
std::optional<Rgb> csv_rgb(const std::vector<std::string>& f, std::size_t c, const std::string& name,
                           const std::string& where) {
  if (f[c].empty() && f[c + 1].empty() && f[c + 2].empty()) return std::nullopt;
  return Rgb{csv_number(f[c], name + "_r", where), csv_number(f[c + 1], name + "_g", where),
             csv_number(f[c + 2], name + "_b", where)};
}

// The lines of a CSV file, read one at a time (no copy of the file's lines: memory stays linear in
// the results, not in the lines; a file of 15 MB of newlines took 650 MB as strings).
class CsvLines {
 public:
  explicit CsvLines(std::string_view bytes) : bytes_(bytes) {}
  // The next line without its "\r\n" or "\n" (false after the last); number() is its 1-based number.
  bool next(std::string_view* line) {
    if (start_ > bytes_.size()) return false;
    std::size_t end = bytes_.find('\n', start_);
    if (end == std::string_view::npos) end = bytes_.size();
    *line = bytes_.substr(start_, end - start_);
    if (!line->empty() && line->back() == '\r') line->remove_suffix(1);
    start_ = end + 1;
    ++number_;
    return true;
  }
  std::size_t number() const { return number_; }

 private:
  std::string_view bytes_;
  std::size_t start_ = 0, number_ = 0;
};

std::vector<Result> parse_csv_results(std::string_view bytes, const std::string& path) {
  CsvLines lines(bytes);
  std::string_view first_line;
  lines.next(&first_line);
  static const std::vector<std::string> kBase = {"id", "f_cos_r", "f_cos_g", "f_cos_b"};
  const auto bad_header = [&] {
    fail(path, "line 1: the CSV header must be id,f_cos_r,f_cos_g,f_cos_b[,pdf][,albedo_r,albedo_g,albedo_b], got " +
                   in_quotes(first_line));
  };
  // The header: id, f_cos_r..b, pdf, albedo_r..b at most; one that cannot be read (more fields, an
  // unterminated quote) is a bad header.
  std::vector<std::string> header;
  try {
    header = csv_fields(first_line, "line 1", 8, "");
  } catch (const std::runtime_error&) {
    bad_header();
  }
  bool has_pdf = false, has_albedo = false;
  {
    std::vector<std::string> expect = kBase;
    std::size_t i = 4;
    if (header.size() > i && header[i] == "pdf") has_pdf = true, expect.push_back("pdf"), ++i;
    if (header.size() > i && header[i] == "albedo_r") {
      has_albedo = true;
      for (const char* c : {"albedo_r", "albedo_g", "albedo_b"}) expect.push_back(c);
    }
    if (header != expect) bad_header();
  }
  const std::size_t columns = 4 + (has_pdf ? 1 : 0) + (has_albedo ? 3 : 0);
  std::vector<Result> out;
  // Memory: the readers' bound (limits.h), each result charged twice its size (the vector's growth)
  // and its id, so that rows of a few bytes cannot take ~40 x the file's size.
  const std::size_t budget = limits::json_memory_budget(bytes.size());
  std::size_t used = 0;
  try {
    for (std::string_view line; lines.next(&line);) {
      if (line.find_first_not_of(" \t") == std::string_view::npos) continue;  // blank lines (the final newline)
      const std::string line_where = "line " + std::to_string(lines.number());
      const std::vector<std::string> f =
          csv_fields(line, line_where, columns, ", the header has " + std::to_string(columns));
      const std::string where = line_where + (f.empty() ? "" : " (id " + in_quotes(f[0]) + ")");
      if (f.size() != columns)
        throw std::runtime_error(where + ": " + std::to_string(f.size()) + " fields, the header has " +
                                 std::to_string(columns));
      if ((used += 2 * sizeof(Result) + f[0].size()) > budget)
        throw std::runtime_error(line_where + ": its results would take more than " + std::to_string(budget >> 20) +
                                 " MiB in memory, 10 x the file's size + 64 MiB (the readers' bound, docs/limits.md)");
      Result r;
      r.id = f[0];
      std::size_t c = 1;
      r.f_cos = csv_rgb(f, c, "f_cos", where);
      c += 3;
      if (has_pdf && !f[c].empty()) r.pdf = csv_number(f[c], "pdf", where);
      c += has_pdf ? 1 : 0;
      if (has_albedo) r.albedo = csv_rgb(f, c, "albedo", where);
      out.push_back(std::move(r));
    }
  } catch (const std::runtime_error& e) {
    fail(path, e.what());
  }
  return out;
}

}  // namespace

std::vector<Result> parse_results(std::string_view bytes, const std::string& path) {
  // A UTF-8 byte-order mark (a spreadsheet's CSV export, some editors' JSON) is not content.
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) fail(path, "the results file is empty");
  std::vector<Result> out = bytes[first] == '{' || bytes[first] == '[' ? parse_json_results(bytes, path) : parse_csv_results(bytes, path);
  if (out.empty()) fail(path, "no results");
  return out;
}

nlohmann::ordered_json results_document(const std::vector<Result>& results) {
  using OJson = nlohmann::ordered_json;
  const auto rgb = [](const Rgb& c) { return OJson::array({c.r, c.g, c.b}); };
  OJson list = OJson::array();
  for (const Result& r : results) {
    if (!r.f_cos && !r.pdf && !r.albedo && !r.emission && !r.delta) continue;  // not supplied
    OJson j{{"id", r.id}};
    if (r.f_cos) j["f_cos"] = rgb(*r.f_cos);
    if (r.pdf) j["pdf"] = *r.pdf;
    if (r.albedo) j["albedo"] = rgb(*r.albedo);
    if (r.emission) j["emission"] = rgb(*r.emission);
    if (r.delta) {
      j["delta"] = OJson::array();
      for (const DeltaExpectation& d : *r.delta)
        j["delta"].push_back(OJson{{"l", {d.l.x, d.l.y, d.l.z}}, {"value", rgb(d.value)}});
    }
    list.push_back(std::move(j));
  }
  return OJson{{"results", list}};
}

std::vector<Result> read_results(const std::string& path) {
  return parse_results(read_file(path, limits::kDocumentBytes), path);
}

void require_f_cos(const std::vector<Vector>& vectors, const std::vector<Result>& results, const std::string& path,
                   const std::string& vectors_path) {
  // The one quantity every vector judges; a result whose f cos is left out or null counts as none.
  std::size_t missing = 0;
  std::string first_missing;
  for (std::size_t i = 0; i < vectors.size(); ++i)
    if (!results[i].f_cos && missing++ == 0) first_missing = vectors[i].id;
  if (missing > 0)
    fail(path, "no result with an f_cos for vector " + in_quotes(first_missing) +
                   (missing > 1 ? " (and " + std::to_string(missing - 1) + " more)" : std::string()) +
                   ": every vector of " + vectors_path + " needs one (--require-all)");
}

std::vector<Result> match_results(const std::vector<Vector>& vectors, std::vector<Result> results,
                                  const std::string& path, const std::string& vectors_path, bool require_all) {
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < vectors.size(); ++i) index[vectors[i].id] = i;
  std::vector<std::optional<Result>> slot(vectors.size());
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto it = index.find(results[i].id);
    if (it == index.end())
      fail(path, "result " + std::to_string(i + 1) + ": id " + in_quotes(results[i].id) + " is not a vector of " +
                     vectors_path);
    if (slot[it->second]) fail(path, "result " + std::to_string(i + 1) + ": duplicate id " + in_quotes(results[i].id));
    slot[it->second] = std::move(results[i]);
  }
  std::vector<Result> out;
  for (std::size_t i = 0; i < vectors.size(); ++i)
    out.push_back(slot[i] ? std::move(*slot[i])
                          : Result{vectors[i].id, std::nullopt, std::nullopt, std::nullopt, std::nullopt, std::nullopt});
  if (require_all) require_f_cos(vectors, out, path, vectors_path);
  return out;
}

}  // namespace dspbr::conformance
