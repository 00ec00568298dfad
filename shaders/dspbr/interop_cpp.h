// The C++ side of the shader library's common subset (shaders/README.md, "The common subset"):
// the GLSL types and built-ins the body uses (vec3, uint, dot, cross, normalize, mix, clamp, ...)
// as single-precision C++17, inside namespace dspbr_shader, so that the body files under
// shaders/dspbr/ compile unchanged as C++, GLSL 450 and HLSL. Float only, IEEE semantics (no
// -ffast-math assumptions), no heap, no exceptions.
#pragma once
#include <cmath>

namespace dspbr_shader {

typedef unsigned int uint;

struct vec3 {
  float x, y, z;
  vec3() : x(0.0f), y(0.0f), z(0.0f) {}
  vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
};

inline vec3 operator+(vec3 a, vec3 b) { return vec3(a.x + b.x, a.y + b.y, a.z + b.z); }
inline vec3 operator-(vec3 a, vec3 b) { return vec3(a.x - b.x, a.y - b.y, a.z - b.z); }
inline vec3 operator*(vec3 a, vec3 b) { return vec3(a.x * b.x, a.y * b.y, a.z * b.z); }
inline vec3 operator/(vec3 a, vec3 b) { return vec3(a.x / b.x, a.y / b.y, a.z / b.z); }
inline vec3 operator*(vec3 a, float s) { return vec3(a.x * s, a.y * s, a.z * s); }
inline vec3 operator*(float s, vec3 a) { return vec3(a.x * s, a.y * s, a.z * s); }
inline vec3 operator/(vec3 a, float s) { return vec3(a.x / s, a.y / s, a.z / s); }
inline vec3 operator-(vec3 a) { return vec3(-a.x, -a.y, -a.z); }
inline vec3& operator+=(vec3& a, vec3 b) { return a = a + b; }
inline vec3& operator-=(vec3& a, vec3 b) { return a = a - b; }
inline vec3& operator*=(vec3& a, vec3 b) { return a = a * b; }
inline vec3& operator*=(vec3& a, float s) { return a = a * s; }

inline float abs(float x) { return std::fabs(x); }
inline int abs(int x) { return x < 0 ? -x : x; }
inline float sqrt(float x) { return std::sqrt(x); }
inline float pow(float x, float y) { return std::pow(x, y); }
inline float exp(float x) { return std::exp(x); }
inline float log(float x) { return std::log(x); }
inline float sin(float x) { return std::sin(x); }
inline float cos(float x) { return std::cos(x); }
inline float acos(float x) { return std::acos(x); }
// floor and ceil without a library call (the x86-64 baseline has no rounding instruction, and
// std::floor is a call there): by the conversion to int, exact below 2^23 in magnitude; every larger
// float, +-inf and NaN is its own floor. The same values as std::floor / std::ceil, the sign of a
// zero result included (x * 0 is -0 for x in (-1, -0], +0 for x in [0, 1)).
inline float floor(float x) {
  if (!(std::fabs(x) < 8388608.0f)) return x;
  const float t = float(int(x));  // towards zero
  return t > x ? t - 1.0f : (t == 0.0f ? x * 0.0f : t);
}
inline float ceil(float x) {
  if (!(std::fabs(x) < 8388608.0f)) return x;
  const float t = float(int(x));
  return t < x ? t + 1.0f : (t == 0.0f ? x * 0.0f : t);
}
// GLSL min/max/clamp: for a NaN argument the result is unspecified in GLSL; the body never relies
// on it (shaders/README.md, "NaN and Inf").
inline float min(float a, float b) { return b < a ? b : a; }
inline float max(float a, float b) { return a < b ? b : a; }
inline int min(int a, int b) { return b < a ? b : a; }
inline int max(int a, int b) { return a < b ? b : a; }
inline float clamp(float x, float lo, float hi) { return min(max(x, lo), hi); }
inline float mix(float a, float b, float t) { return a + (b - a) * t; }
inline vec3 min(vec3 a, vec3 b) { return vec3(min(a.x, b.x), min(a.y, b.y), min(a.z, b.z)); }
inline vec3 max(vec3 a, vec3 b) { return vec3(max(a.x, b.x), max(a.y, b.y), max(a.z, b.z)); }
inline vec3 mix(vec3 a, vec3 b, float t) { return a + (b - a) * t; }
inline float dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline vec3 cross(vec3 a, vec3 b) {
  return vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
inline float length(vec3 a) { return std::sqrt(dot(a, a)); }
inline vec3 normalize(vec3 a) { return a / length(a); }
inline bool isnan(float x) { return std::isnan(x); }
// The flakes' 64-bit generator words (flakes.glsl: two 32-bit words, for GLSL and HLSL, which have
// no 64-bit integers) in native 64-bit arithmetic: the same values in a third of the instructions.
#define DSPBR_NATIVE_U64 1
struct DspbrU64 {
  uint hi;
  uint lo;
};
inline unsigned long long dspbr_u64_bits(DspbrU64 a) { return ((unsigned long long)a.hi << 32u) | a.lo; }
inline DspbrU64 dspbr_u64_of_bits(unsigned long long v) {
  DspbrU64 r;
  r.hi = uint(v >> 32u);
  r.lo = uint(v);
  return r;
}
inline DspbrU64 dspbr_u64(uint hi, uint lo) { return dspbr_u64_of_bits(((unsigned long long)hi << 32u) | lo); }
inline DspbrU64 dspbr_u64_add(DspbrU64 a, DspbrU64 b) { return dspbr_u64_of_bits(dspbr_u64_bits(a) + dspbr_u64_bits(b)); }
inline DspbrU64 dspbr_u64_xor(DspbrU64 a, DspbrU64 b) { return dspbr_u64_of_bits(dspbr_u64_bits(a) ^ dspbr_u64_bits(b)); }
inline DspbrU64 dspbr_u64_shr(DspbrU64 a, uint n) { return dspbr_u64_of_bits(dspbr_u64_bits(a) >> n); }  // 0 < n < 64
inline DspbrU64 dspbr_u64_mul(DspbrU64 a, DspbrU64 b) { return dspbr_u64_of_bits(dspbr_u64_bits(a) * dspbr_u64_bits(b)); }
inline bool isinf(float x) { return std::isinf(x); }

}  // namespace dspbr_shader

// The common subset's keywords (shaders/README.md): functions are inline, constants static,
// large read-only parameters const references (a path tracer's compiler does not always inline,
// and a DspbrBsdf copied per call cost more than the tables it reads), out / inout parameters
// references, atan2 under one name.
#define DSPBR_FN inline
#define DSPBR_CONST static const
#define DSPBR_IN(T) const T&
#define DSPBR_OUT(T) T&
#define DSPBR_INOUT(T) T&
#define dspbr_atan2(y, x) std::atan2(y, x)
