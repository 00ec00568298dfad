#include "dspbr/io/read_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <set>
#include <stdexcept>
#include <vector>

#include "dspbr/io/json_fields.h"
#include "dspbr/io/message.h"
#include "dspbr/limits.h"

namespace dspbr {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw std::runtime_error(path + what); }

const char* file_kind(mode_t mode) {
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a plain file";
}

}  // namespace

std::string bytes_text(std::uint64_t n) {
  char buf[32];
  if (n >= (std::uint64_t(1) << 30)) std::snprintf(buf, sizeof buf, "%.1f GB", double(n) / double(1 << 30));
  else if (n >= (std::uint64_t(1) << 20)) std::snprintf(buf, sizeof buf, "%.1f MB", double(n) / double(1 << 20));
  else std::snprintf(buf, sizeof buf, "%llu bytes", static_cast<unsigned long long>(n));
  return buf;
}

RegularFile::RegularFile(const std::string& path) : path_(path) {
  // A C path ends at a NUL byte: "a.json\0x" (possible from Python) would open "a.json".
  if (path.find('\0') != std::string::npos) fail(quote_input(path), ": a file name cannot hold a NUL byte");
  if (path.empty()) fail("''", ": an empty file name names no file");
  // O_NONBLOCK: opening a FIFO without a writer would block; it is refused after fstat instead.
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd_ < 0) {
    const int err = errno;
    if (err == ENOENT) fail(path, " does not exist");
    if (err == ENXIO) fail(path, " is not a regular file (a socket or a device)");
    fail(path, std::string(" cannot be read: ") + std::strerror(err));
  }
  struct stat st {};
  if (::fstat(fd_, &st) != 0) {
    const int err = errno;
    ::close(fd_);
    fail(path, std::string(" cannot be read: ") + std::strerror(err));
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd_);
    if (S_ISDIR(st.st_mode)) fail(path, " is a directory");
    fail(path, std::string(" is not a regular file (") + file_kind(st.st_mode) + ")");
  }
  size_ = static_cast<std::uint64_t>(st.st_size);
}

RegularFile::~RegularFile() { ::close(fd_); }

std::string RegularFile::read(std::uint64_t max_bytes) const {
  std::string out;
  out.reserve(static_cast<std::size_t>(std::min(size_, max_bytes)));
  char buf[65536];
  while (out.size() < max_bytes) {
    const ssize_t n = ::pread(fd_, buf, static_cast<std::size_t>(std::min<std::uint64_t>(sizeof buf, max_bytes - out.size())),
                              static_cast<off_t>(out.size()));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(path_, std::string(" cannot be read: ") + std::strerror(errno));
    if (n == 0) break;
    out.append(buf, static_cast<std::size_t>(n));
  }
  return out;
}

void require_at_most(const std::string& path, std::uint64_t size, std::uint64_t max_bytes) {
  if (size > max_bytes)
    fail(path, " is " + bytes_text(size) + ", larger than the limit of " + bytes_text(max_bytes) +
                   " for this kind of file (docs/limits.md)");
}

std::string read_file(const std::string& path, std::uint64_t max_bytes) {
  const RegularFile f(path);
  // The size from fstat, and again while reading (a file that grows meanwhile).
  require_at_most(path, f.size(), max_bytes);
  std::string out = f.read(max_bytes + 1);
  require_at_most(path, out.size(), max_bytes);
  return out;
}

std::string sniff_format(std::string_view bytes) {
  struct Magic {
    std::string_view start;
    const char* name;
  };
  // Signatures from each format's specification (first bytes of the file).
  static const Magic kMagics[] = {
      {std::string_view("\x89PNG\r\n\x1a\n", 8), "a PNG image"},
      {std::string_view("\xff\xd8\xff", 3), "a JPEG image"},
      {"glTF", "a binary glTF (GLB)"},
      {std::string_view("\x76\x2f\x31\x01", 4), "an OpenEXR image"},
      {std::string_view("PK\x03\x04", 4), "a ZIP archive"},
      {std::string_view("\x1f\x8b", 2), "a gzip file"},
      {"%PDF-", "a PDF document"},
  };
  for (const auto& m : kMagics)
    if (bytes.substr(0, m.start.size()) == m.start) return m.name;
  return "";
}

namespace {

// Throws when arrays and objects nest deeper than limits::kJsonDepth (before parsing: the parser
// itself is iterative, but copies, merges and dumps of the document recurse per level). Brackets
// inside strings do not count.
void check_nesting(std::string_view text, const std::string& path) {
  int depth = 0;
  long line = 1;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (c == '\n') ++line;
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limits::kJsonDepth)
        throw std::runtime_error(path + ": JSON nested deeper than " + std::to_string(limits::kJsonDepth) +
                                 " levels (line " + std::to_string(line) + ")");
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

// Where the parser is: one frame per open array or object, with the element being read.
struct JsonCursor {
  struct Frame {
    bool array = false;
    std::size_t index = 0;  // arrays: the element being read
    std::string key;        // objects: the member being read
    std::set<std::string> keys;
  };
  std::vector<Frame> frames;

  // The JSON path of the first `n` frames' current elements ("tables.GGX_E.values[3]").
  std::string path(std::size_t n) const {
    std::string p;
    for (std::size_t i = 0; i < n && i < frames.size(); ++i)
      p = frames[i].array ? json_fields::index_path(p, frames[i].index)
                          : json_fields::member_path(p, quote_input(frames[i].key));
    return p;
  }
  std::string here() const {
    const std::string p = path(frames.size());
    return p.empty() ? "the top level" : p;
  }
  void element_done() {
    if (!frames.empty() && frames.back().array) ++frames.back().index;
  }
};

}  // namespace

// The DOM builder of nlohmann's plain (linear) SAX parser with the reader's checks on the way: the
// cursor (the JSON path in messages), I-JSON's unique member names (RFC 7493, 2.3) and the value
// budget. (The callback parser, used before, scanned an object's or array's earlier siblings each
// time one closed: quadratic in the members of one object or array.) The base's methods are not
// virtual: sax_parse calls these, which hide them.
template <class Json>
class JsonReader : public nlohmann::detail::json_sax_dom_parser<Json> {
  using Base = nlohmann::detail::json_sax_dom_parser<Json>;

 public:
  using string_t = typename Json::string_t;
  JsonReader(Json& doc, JsonCursor& cursor, const std::string& path, std::size_t budget_bytes)
      : Base(doc, true), cursor_(cursor), path_(path), budget_(budget_bytes) {}

  bool null() { return scalar(limits::kJsonScalarBytes), Base::null(); }
  bool boolean(bool x) { return scalar(limits::kJsonScalarBytes), Base::boolean(x); }
  bool number_integer(typename Json::number_integer_t x) {
    return scalar(limits::kJsonScalarBytes), Base::number_integer(x);
  }
  bool number_unsigned(typename Json::number_unsigned_t x) {
    return scalar(limits::kJsonScalarBytes), Base::number_unsigned(x);
  }
  bool number_float(typename Json::number_float_t x, const string_t& s) {
    return scalar(limits::kJsonScalarBytes), Base::number_float(x, s);
  }
  bool string(string_t& x) { return scalar(limits::kJsonStringBytes + x.size()), Base::string(x); }
  bool start_object(std::size_t n) {
    count(limits::kJsonContainerBytes);
    cursor_.frames.push_back({});
    return Base::start_object(n);
  }
  bool start_array(std::size_t n) {
    count(limits::kJsonContainerBytes);
    cursor_.frames.push_back(JsonCursor::Frame{true, 0, {}, {}});
    return Base::start_array(n);
  }
  bool key(string_t& k) {
    count(limits::kJsonKeyBytes + k.size());
    auto& f = cursor_.frames.back();
    f.key = k;
    if (!f.keys.insert(f.key).second)
      throw std::runtime_error(path_ + ": duplicate key \"" + quote_input(f.key) + "\" in " +
                               (cursor_.frames.size() > 1 ? cursor_.path(cursor_.frames.size() - 1) : "the top-level object"));
    return Base::key(k);
  }
  bool end_object() { return close(), Base::end_object(); }
  bool end_array() { return close(), Base::end_array(); }

 private:
  // Charges a value's memory; over the budget: refused while reading.
  void count(std::size_t bytes) {
    if ((used_ += bytes) > budget_)
      throw std::runtime_error(path_ + ": its JSON values would take more than " + std::to_string(budget_ >> 20) +
                               " MiB in memory, 10 x the file's size + 64 MiB (the readers' bound, docs/limits.md)");
  }
  void scalar(std::size_t bytes) {
    count(bytes);
    cursor_.element_done();
  }
  void close() {
    cursor_.frames.pop_back();
    cursor_.element_done();
  }
  JsonCursor& cursor_;
  const std::string& path_;
  std::size_t budget_, used_ = 0;
};

template <class Json>
Json parse_json(std::string_view text, const std::string& path, const std::string& what) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) throw std::runtime_error(path + " is empty");
  if (const std::string format = sniff_format(text); !format.empty())
    throw std::runtime_error(path + " is not a " + what + " (it starts like " + format + ")");
  // The parser takes a NUL byte for the end of the input (and would ignore what follows); JSON
  // text holds none (RFC 8259: control characters in strings are escaped).
  if (const auto nul = text.find('\0'); nul != std::string_view::npos)
    throw std::runtime_error(path + ": a NUL byte at offset " + std::to_string(nul) + " (not JSON text)");
  check_nesting(text, path);
  JsonCursor cursor;
  Json doc;
  JsonReader<Json> reader(doc, cursor, path, limits::json_memory_budget(text.size()));
  try {
    Json::sax_parse(text.begin(), text.end(), &reader);
    return doc;
  } catch (const nlohmann::json::out_of_range&) {
    // The parser's only out_of_range while parsing: a number beyond double's range (1e999).
    throw std::runtime_error(path + ": the number at " + cursor.here() + " overflows a double");
  } catch (const nlohmann::json::parse_error& e) {
    // nlohmann's message: "[json.exception.parse_error.101] parse error at line L, column C: ...".
    std::string detail = e.what();
    const std::string marker = "parse error at ";
    if (const auto pos = detail.find(marker); pos != std::string::npos) detail = "at " + detail.substr(pos + marker.size());
    throw std::runtime_error(path + ": malformed JSON " + quote_input(detail));
  }
}

template nlohmann::json parse_json<nlohmann::json>(std::string_view, const std::string&, const std::string&);
template nlohmann::ordered_json parse_json<nlohmann::ordered_json>(std::string_view, const std::string&,
                                                                   const std::string&);

}  // namespace dspbr
