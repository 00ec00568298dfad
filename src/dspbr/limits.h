// The limits on input the project accepts, one constant per concept, each stated in docs/limits.md.
// They keep every reader and command within seconds and bounded memory on hostile input
// (deep nesting, long inheritance chains, expanding references, huge sizes); legal DSPBR
// material, scenes and tables stay far inside them.
#pragma once
#include <cstddef>
#include <cstdint>

namespace dspbr::limits {

// Nesting depth of any JSON document read (parameter definitions, material instances, glTF/GLB,
// table files): arrays and objects inside each other. params-2025x.json and the validation
// scenes nest 6 deep; recursive code (merge, $ref resolution, dump) stays far from the stack's end.
inline constexpr int kJsonDepth = 256;

// Materials in one inheritance chain of a parameter definition file ("inherits", spec appendix
// "Inheritance"): params-2025x.json has 3.
inline constexpr int kInheritanceDepth = 64;

// Nested "$ref" resolutions inside one reference (a reference whose target holds references...).
inline constexpr int kRefDepth = 32;

// JSON values (numbers, strings, arrays, objects...) of a parameter definition file once
// inheritance is merged and every "$ref" is replaced by its target: bounds the memory and output
// of files whose references or bases double at each step. params-2025x.json resolves to ~3800.
inline constexpr std::size_t kResolvedJsonValues = std::size_t(1) << 20;

// The memory a parsed JSON document may take, by the file's size: 10 x bytes + 64 MiB, so that the
// process (dspbr-full starts at about 136 MB) stays within 10 x the file's size + 200 MB. The
// readers count it while reading, each value at a cost that bounds nlohmann::json's (Linux x86-64,
// glibc; maximum RSS over arrays of 2 to 4 million values): an object or array 160 bytes
// (measured: {} 81 to 98, [] 50 to 66), a member's key 96 (a member {"k": 0} 111 per value, 222 with
// its number), a string 96 plus its length ("" 62 to 79), any other value 48 (0 16 to 31).
inline constexpr std::size_t kJsonContainerBytes = 160, kJsonKeyBytes = 96, kJsonStringBytes = 96,
                             kJsonScalarBytes = 48;
inline constexpr std::size_t json_memory_budget(std::size_t bytes) { return 10 * bytes + (std::size_t(64) << 20); }

// Samples along one axis of a table, generated (--size) or read (table files of either layout).
inline constexpr int kTableAxisSize = 4096;
// Cells of one table (the product of its axis sizes), generated or read.
inline constexpr std::size_t kTableCells = std::size_t(1) << 24;

// Bytes of one input file, checked (fstat) before it is read; only regular files are read at
// all (io/read_file.h). Parameter definitions, material instances and fit documents: the
// largest committed one has 95 kB.
inline constexpr std::uint64_t kDocumentBytes = std::uint64_t(16) << 20;
// Table files of either layout: the committed renderer file has 2 MB; a table at the cell limit
// written as JSON needs about 0.7 GB.
inline constexpr std::uint64_t kTableFileBytes = std::uint64_t(1) << 30;
// glTF and GLB files (read whole; the buffer files they name are only sized, never read): the
// validation scenes have at most 64 kB.
inline constexpr std::uint64_t kGltfBytes = std::uint64_t(256) << 20;

// Materials of one glTF, and of one `scene analyze` run: an analysis costs up to ~11 kB per material
// (--json --parameters), a material as little as 3 bytes of glTF ("{},"): 65,536 empty materials
// (197 kB) took 723 MB. 10,000 keeps a run within 10 x its input + 200 MB; the validation scenes
// have 1 to 3 each.
inline constexpr std::size_t kSceneMaterials = 10000;

// Worker threads (--threads, Python threads=): 0 means all cores; far above the cores of any
// machine (TBB fails near INT_MAX).
inline constexpr int kThreads = 1024;

}  // namespace dspbr::limits
