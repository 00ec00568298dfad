// Reading user-given input files (src/dspbr/io/read_file.h): every failure is one line naming
// the file and the problem. Expected texts are the ones the header documents.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "dspbr/io/read_file.h"

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
  EXPECT_EQ(read_file(write_bytes("bytes.bin", bytes)), bytes);
}

TEST(ReadFile, MissingFileAndDirectoryAreNamed) {
  const std::string missing = temp_path("no_such_file.json");
  EXPECT_EQ(error_of([&] { read_file(missing); }), missing + " does not exist");
  const std::string dir = temp_path("a_folder.gltf");
  std::filesystem::create_directories(dir);
  EXPECT_EQ(error_of([&] { read_file(dir); }), dir + " is a directory");
  EXPECT_EQ(error_of([&] { read_json_file(dir, "glTF file"); }), dir + " is a directory");
}

TEST(ReadFile, KnownBinaryFormatsAreNamedInsteadOfAJsonError) {
  const std::string png = write_bytes("image.gltf", kPng);
  EXPECT_EQ(error_of([&] { read_json_file(png, "glTF file"); }), png + " is not a glTF file (it starts like a PNG image)");
  EXPECT_EQ(sniff_format("\xff\xd8\xff\xe0"), "a JPEG image");
  EXPECT_EQ(sniff_format(std::string("PK\x03\x04", 4)), "a ZIP archive");
  EXPECT_EQ(sniff_format("{\"asset\": {}}"), "");
  EXPECT_EQ(sniff_format(""), "");
}

TEST(ReadFile, MalformedJsonIsOneLineWithoutRawBytes) {
  const std::string path = write_bytes("bad.json", "{\"a\": 1,\n \"b\": \xe9t\xe9\n}");
  const std::string e = error_of([&] { read_json_file(path, "material instance file"); });
  EXPECT_EQ(e.rfind(path + ": malformed JSON at line 2, column 7", 0), 0u) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  EXPECT_EQ(e.find('\xe9'), std::string::npos) << e;  // a Latin-1 byte, not UTF-8
  EXPECT_NE(e.find("\\xe9"), std::string::npos) << e;
  const std::string blank = write_bytes("blank.json", " \n\t");
  EXPECT_EQ(error_of([&] { read_json_file(blank, "material instance file"); }), blank + " is empty");
}

TEST(ReadFile, ParsesJsonKeepingOrderWhenAsked) {
  const std::string path = write_bytes("ordered.json", "{\"b\": 1, \"a\": [true, null]}");
  const auto ordered = read_json_file<nlohmann::ordered_json>(path, "file");
  EXPECT_EQ(ordered.begin().key(), "b");
  EXPECT_EQ(read_json_file(path, "file")["a"], nlohmann::json::array({true, nullptr}));
}
