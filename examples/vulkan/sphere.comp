#version 450
// A renderer's use of the shader library (docs/renderer.md): spheres under a point light shaded
// with the whole DSPBR BSDF (dspbr.glsl), one invocation per pixel, one tile of tile x tile pixels
// per material, left to right. examples/vulkan/sphere.cpp uploads the tables (texture mode,
// bindings 2..7) and the materials (DSPBR_MATERIAL_PACK), runs it and compares with the C++
// reference BSDF.
#extension GL_GOOGLE_include_directive : require
// The tables as R32F textures at bindings 2..7 of set 0; bindings 0 and 1 are this shader's buffers.
#define DSPBR_LOOKUP_BINDING_BASE 2
#include "dspbr.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
// The scene (sphere_scene.h, Scene::buffer): the unit sphere at the origin, then the materials.
layout(std430, binding = 0) readonly buffer Scene {
  vec4 eye;    // camera position (looking down -z, y up), w = tan(half the field of view)
  vec4 light;  // point light position, w = its intensity I
  float materials[];  // DSPBR_MATERIAL_FLOATS per material
};
layout(std430, binding = 1) writeonly buffer Image { vec4 pixels[]; };  // RGBA, row by row
layout(push_constant) uniform Size { uint tile; uint tiles; } size;

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  uint width = size.tile * size.tiles;
  if (p.x >= width || p.y >= size.tile) return;
  // The primary ray through the pixel's centre.
  vec2 ndc = (vec2(float(p.x % size.tile), float(p.y)) + 0.5) / float(size.tile) * 2.0 - 1.0;
  vec3 d = normalize(vec3(ndc.x * eye.w, -ndc.y * eye.w, -1.0));
  // The nearer root of |eye + t d| = 1.
  float b = dot(eye.xyz, d), disc = b * b - (dot(eye.xyz, eye.xyz) - 1.0);
  vec4 radiance = vec4(0.0);
  if (disc >= 0.0) {
    vec3 x = eye.xyz - (b + sqrt(disc)) * d;
    vec3 n = normalize(x), v = -d, to_light = light.xyz - x;
    float d2 = dot(to_light, to_light);
    vec3 l = to_light * inversesqrt(d2);
    DspbrMaterial m;
    DSPBR_MATERIAL_UNPACK(m, materials, (p.x / size.tile) * DSPBR_MATERIAL_FLOATS);
    // The shading frame: the normal and the x axis made orthogonal to it (sphere_scene.h).
    DspbrBsdf bsdf = dspbr_prepare(m, dspbr_frame_from_normal_tangent(n, vec3(1.0, 0.0, 0.0)),
                                   dspbr_default_options());
    // L = f(v, l) |n.l| I / d^2: a point light of intensity I at distance d, seen through the
    // surface where it is behind it (the transmission lobes; an example of the BSDF, not of shadows).
    radiance = vec4(dspbr_eval(bsdf, v, l) * (abs(dot(n, l)) * light.w / d2), 1.0);
  }
  pixels[p.y * width + p.x] = radiance;
}
