// Reading user-given input files (src/dspbr/io/read_file.h): every failure is one line naming
// the file and the problem. Expected texts are the ones the header documents.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "dspbr/io/message.h"
#include "dspbr/io/read_file.h"
#include "dspbr/limits.h"

using namespace dspbr;

namespace {

std::string temp_path(const std::string& name) { return ::testing::TempDir() + "/read_file_" + name; }

std::string write_bytes(const std::string& name, const std::string& bytes) {
  const std::string path = temp_path(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// The 8-byte PNG signature (PNG specification, section 5.2) and the start of an IHDR chunk.
const std::string kPng("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);

}  // namespace

TEST(ReadFile, ReadsEveryByte) {
  const std::string bytes("a\0b\r\n\xff", 6);
  EXPECT_EQ(read_file(write_bytes("bytes.bin", bytes), 6), bytes);
}

TEST(ReadFile, MissingFileAndDirectoryAreNamed) {
  const std::string missing = temp_path("no_such_file.json");
  EXPECT_EQ(error_of([&] { read_file(missing, 1); }), missing + " does not exist");
  const std::string dir = temp_path("a_folder.gltf");
  std::filesystem::create_directories(dir);
  EXPECT_EQ(error_of([&] { read_file(dir, 1); }), dir + " is a directory");
  EXPECT_EQ(error_of([&] { read_json_file(dir, "glTF file", limits::kGltfBytes); }), dir + " is a directory");
}

TEST(ReadFile, KnownBinaryFormatsAreNamedInsteadOfAJsonError) {
  const std::string png = write_bytes("image.gltf", kPng);
  EXPECT_EQ(error_of([&] { read_json_file(png, "glTF file", limits::kGltfBytes); }), png + " is not a glTF file (it starts like a PNG image)");
  EXPECT_EQ(sniff_format("\xff\xd8\xff\xe0"), "a JPEG image");
  EXPECT_EQ(sniff_format(std::string("PK\x03\x04", 4)), "a ZIP archive");
  EXPECT_EQ(sniff_format("{\"asset\": {}}"), "");
  EXPECT_EQ(sniff_format(""), "");
}

TEST(ReadFile, MalformedJsonIsOneLineWithoutRawBytes) {
  const std::string path = write_bytes("bad.json", "{\"a\": 1,\n \"b\": \xe9t\xe9\n}");
  const std::string e = error_of([&] { read_json_file(path, "material instance file", limits::kDocumentBytes); });
  EXPECT_EQ(e.rfind(path + ": malformed JSON at line 2, column 7", 0), 0u) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  EXPECT_EQ(e.find('\xe9'), std::string::npos) << e;  // a Latin-1 byte, not UTF-8
  EXPECT_NE(e.find("\\xe9"), std::string::npos) << e;
  const std::string blank = write_bytes("blank.json", " \n\t");
  EXPECT_EQ(error_of([&] { read_json_file(blank, "material instance file", limits::kDocumentBytes); }), blank + " is empty");
}

TEST(ReadFile, ParsesJsonKeepingOrderWhenAsked) {
  const std::string path = write_bytes("ordered.json", "{\"b\": 1, \"a\": [true, null]}");
  const auto ordered = read_json_file<nlohmann::ordered_json>(path, "file", limits::kDocumentBytes);
  EXPECT_EQ(ordered.begin().key(), "b");
  EXPECT_EQ(read_json_file(path, "file", limits::kDocumentBytes)["a"], nlohmann::json::array({true, nullptr}));
}

TEST(ReadFile, SizeLimitIsCheckedBeforeReading) {
  const std::string path = write_bytes("hundred.json", std::string(100, ' '));
  EXPECT_EQ(read_file(path, 100).size(), 100u);
  EXPECT_EQ(error_of([&] { read_file(path, 99); }),
            path + " is 100 bytes, larger than the limit of 99 bytes for this kind of file (docs/limits.md)");
}

// A FIFO without a writer would block a plain open() forever, /dev/zero never ends: both are
// refused from their type before a byte is read (the test would hang, not fail, without it).
TEST(ReadFile, FifoAndDeviceAreRefusedAtOnce) {
  const std::string fifo = temp_path("pipe.gltf");
  std::filesystem::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(error_of([&] { read_file(fifo, limits::kGltfBytes); }), fifo + " is not a regular file (a FIFO)");
  EXPECT_EQ(error_of([&] { read_file("/dev/zero", limits::kGltfBytes); }),
            "/dev/zero is not a regular file (a character device)");
}

TEST(ReadFile, DuplicateKeysAreRefusedWithTheirPath) {
  const std::string nested = write_bytes("dup.json", R"({"a": [0, {"b": 1, "c": 2, "b": 3}]})");
  EXPECT_EQ(error_of([&] { read_json_file(nested, "file", limits::kDocumentBytes); }),
            nested + ": duplicate key \"b\" in a[1]");
  const std::string top = write_bytes("dup_top.json", R"({"x": 1, "x": 1})");
  EXPECT_EQ(error_of([&] { read_json_file(top, "file", limits::kDocumentBytes); }),
            top + ": duplicate key \"x\" in the top-level object");
  // The same key in two different objects is fine.
  const std::string ok = write_bytes("dup_ok.json", R"({"a": {"x": 1}, "b": {"x": 2}})");
  EXPECT_EQ(read_json_file(ok, "file", limits::kDocumentBytes)["b"]["x"], 2);
}

TEST(ReadFile, NulByteAndOverflowingNumbersAreNamed) {
  // The parser would stop at the NUL and accept the document before it.
  const std::string nul = write_bytes("nul.json", std::string("{}\0{\"hidden\": 1}", 16));
  EXPECT_EQ(error_of([&] { read_json_file(nul, "file", limits::kDocumentBytes); }),
            nul + ": a NUL byte at offset 2 (not JSON text)");
  const std::string trailing = write_bytes("trailing.json", "{\"a\": 1} {\"b\": 2}");
  EXPECT_EQ(error_of([&] { read_json_file(trailing, "file", limits::kDocumentBytes); }).rfind(trailing + ": malformed JSON at line 1, column 10: syntax error while parsing value - unexpected '{'; expected end of input", 0), 0u)
      << error_of([&] { read_json_file(trailing, "file", limits::kDocumentBytes); });
  const std::string big = write_bytes("big.json", R"({"t": {"values": [1, 2, 1e999]}})");
  EXPECT_EQ(error_of([&] { read_json_file(big, "file", limits::kDocumentBytes); }),
            big + ": the number at t.values[2] overflows a double");
  // The largest double and a subnormal are numbers like any other.
  const std::string edge = write_bytes("edge.json", R"([1.7976931348623157e308, 4.9e-324])");
  const auto v = read_json_file(edge, "file", limits::kDocumentBytes);
  EXPECT_EQ(v[0].get<double>(), 1.7976931348623157e308);
  EXPECT_GT(v[1].get<double>(), 0.0);
}

TEST(ReadFile, AHugeKeyIsCutInTheMessage) {
  const std::string key(1 << 20, 'k');
  const std::string path = write_bytes("huge_key.json", "{\"" + key + "\": 1, \"" + key + "\": 2}");
  const std::string e = error_of([&] { read_json_file(path, "file", limits::kDocumentBytes); });
  EXPECT_EQ(e, path + ": duplicate key \"" + std::string(kQuoteChars, 'k') + "...\" in the top-level object");
}

TEST(Message, QuotedInputIsPrintableAndCut) {
  EXPECT_EQ(quote_input("a\nb\x1b[31m\xc3\xa9"), "a\\x0ab\\x1b[31m\\xc3\\xa9");
  EXPECT_EQ(quote_input(std::string(kQuoteChars, 'x')), std::string(kQuoteChars, 'x'));
  EXPECT_EQ(quote_input(std::string(kQuoteChars + 1, 'x')), std::string(kQuoteChars, 'x') + "...");
  // A whole message keeps UTF-8 (file names) but no control character.
  EXPECT_EQ(one_line("caf\xc3\xa9.gltf\nline two\r\x7f"), "caf\xc3\xa9.gltf\\x0aline two\\x0d\\x7f");
}
