// Reading input files with one-line error messages that name the file and the problem
// (std::runtime_error): missing, a directory, not a regular file (FIFOs, devices and sockets are
// refused at once: the file is opened without blocking and checked with fstat), larger than its
// limit (limits.h, checked before reading), unreadable, empty, or not strict JSON — saying what
// the file starts like when it is a well-known binary format. Used by every reader of user-given
// files (parameter definitions, material instances, glTF scenes and their buffers, table files,
// fit documents).
#pragma once
#include <nlohmann/json.hpp>
#include <cstdint>
#include <string>
#include <string_view>

namespace dspbr {

// An open regular file (closed by the destructor).
class RegularFile {
 public:
  // Throws "<path> does not exist", "<path> is a directory", "<path> is not a regular file (a
  // FIFO)" (device, socket) or "<path> cannot be read: <reason>".
  explicit RegularFile(const std::string& path);
  ~RegularFile();
  RegularFile(const RegularFile&) = delete;
  RegularFile& operator=(const RegularFile&) = delete;
  std::uint64_t size() const { return size_; }
  // Up to `max_bytes` from the start; throws "<path> cannot be read: <reason>".
  std::string read(std::uint64_t max_bytes) const;

 private:
  std::string path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

// The whole file, a regular file of at most `max_bytes` (else "<path> is 2.1 GB, larger than the
// limit of 16 MB for this kind of file (docs/limits.md)").
std::string read_file(const std::string& path, std::uint64_t max_bytes);
// Throws read_file's "<path> is ..., larger than the limit of ..." when size > max_bytes: for a
// file read under one limit and found to be a kind with a smaller one.
void require_at_most(const std::string& path, std::uint64_t size, std::uint64_t max_bytes);

// A byte count as the messages write it: "22.8 MB", "16.0 MB", "512 bytes".
std::string bytes_text(std::uint64_t n);

// What `bytes` start like when they are a well-known non-JSON format ("a PNG image",
// "a JPEG image", "a binary glTF (GLB)", "an OpenEXR image", "a ZIP archive", "a gzip file",
// "a PDF document"), else "".
std::string sniff_format(std::string_view bytes);

// Parses `text`, the JSON content of `path` (a `what`, e.g. "glTF file"), strictly: RFC 8259 with
// the rules of I-JSON (RFC 7493). Throws "<path> is empty" for blank text, "<path> is not a
// <what> (it starts like a PNG image)" when sniff_format recognizes the bytes, "<path>: JSON
// nested deeper than N levels (line L)" past limits::kJsonDepth, "<path>: duplicate key \"k\" at
// <JSON path>", "<path>: the number at <JSON path> overflows a double", "<path>: a NUL byte at
// offset N" and, on malformed JSON (bytes after the document included), "<path>: malformed JSON
// at line L, column C: <reason>". Bytes outside printable ASCII in quoted input are written \xNN
// and quotes are cut at ~200 characters, so the message stays one line.
template <class Json = nlohmann::json>
Json parse_json(std::string_view text, const std::string& path, const std::string& what);

// read_file + parse_json.
template <class Json = nlohmann::json>
Json read_json_file(const std::string& path, const std::string& what, std::uint64_t max_bytes) {
  return parse_json<Json>(read_file(path, max_bytes), path, what);
}

extern template nlohmann::json parse_json<nlohmann::json>(std::string_view, const std::string&, const std::string&);
extern template nlohmann::ordered_json parse_json<nlohmann::ordered_json>(std::string_view, const std::string&,
                                                                          const std::string&);

}  // namespace dspbr
