// The directional albedo of a prepared BSDF at v, as the conformance generator computes it
// (src/dspbr/conformance/vector_set.cpp, albedo_quadrature at its fine resolution): a product
// rule over both hemispheres, 32 panels x 4 Gauss-Legendre nodes in cos theta_l by 128 midpoints
// in phi, of f |cos| (256 cos-theta nodes, each a loop over phi: dspbr_test_albedo_node); the Dirac
// lobes are added by the host (shader_material.h, delta_lobes). Common subset: the C++ runner sums
// the nodes in one call, the device kernels in one invocation per node (kernel_common.glsl).

DSPBR_CONST int DSPBR_TEST_ALBEDO_NODES = 256;

DSPBR_FN float dspbr_test_gl4_x(int i) { return i == 0 ? -0.8611363116f : (i == 1 ? -0.3399810436f : (i == 2 ? 0.3399810436f : 0.8611363116f)); }
DSPBR_FN float dspbr_test_gl4_w(int i) { return (i == 0 || i == 3) ? 0.3478548451f : 0.6521451549f; }

// The phi loop of cos-theta node `node` (side node / 128, panel (node / 4) % 32, Gauss node node % 4).
DSPBR_FN vec3 dspbr_test_albedo_node(DspbrBsdf b, vec3 v, int node) {
  int side = node / 128, p = (node / 4) % 32, i = node % 4;
  float h = 1.0f / 32.0f, dphi = 2.0f * dspbr_pi / 128.0f;
  float mu = (float(p) + 0.5f) * h + 0.5f * h * dspbr_test_gl4_x(i);
  float w = dspbr_test_gl4_w(i) * 0.5f * h * mu * dphi;
  float s = sqrt(max(0.0f, 1.0f - mu * mu));
  vec3 sum = dspbr_splat(0.0f);
  for (int j = 0; j < 128; ++j) {
    float phi = (float(j) + 0.5f) * dphi;
    sum += dspbr_eval(b, v, vec3(s * cos(phi), s * sin(phi), side == 0 ? mu : -mu)) * w;
  }
  return sum;
}
