// A generic mixture of lobes on one side of the surface (v.z > 0 of the side's coordinates), with
// the spec's layering factors between them (spec "Putting It All Together"):
//   f(v, l) = Sum_k f_k(v, l) L_k(v, l) s
// where L_k is the factor of lobe k's layer on the layers below, s a factor above every layer
// (the cut-out opacity, bsdf/cut_out.h):
//   Core:          (1 - c max(F_c(v.n_c), F_c(l.n_c))) min(1 - rho_hat E_b(v.n), 1 - rho_hat E_b(l.n))
//   Sheen, Flake:  (1 - c max(F_c(v.n_c), F_c(l.n_c)))
//   Coat:          1   (and nothing towards the other side of the surface)
// Lobes live in the core shading frame, the coat lobe in the clearcoat frame.
//
// Sampling: a lobe is chosen with probability proportional to its selection weight
// (Lobe::sampling_weight times its layer factor at (v, v)), each present lobe at least
// kMinSelectionFraction of the largest (select_lobes); pdf(v, l) is the mixture density over the
// non-delta lobes. Fixed capacity: no allocation per call. The core's reflection, multiple-scattering
// and diffuse lobes (a closed set) are called without virtual dispatch, the others through Lobe;
// the local directions of an identity core frame are the world ones (no transform).
#pragma once
#include <array>
#include <memory>
#include <optional>

#include "dspbr/bsdf/lobe.h"
#include "dspbr/bsdf/sheen_lobe.h"
#include "dspbr/frame.h"

namespace dspbr {

// A direction closer to the horizon of a lobe's frame than this (|cos| < 1e-9) is on it: the lobe's
// value and density there are 0 and it samples nothing from there. Below it the lobes' powers of
// cos underflow (found by the fourth fresh tester's pass: NaN at cos 1e-156, values wrong by
// orders of magnitude from cos 1e-17 down); f cos is below 1e-9 f there anyway.
constexpr double kHorizonCos = 1e-9;

// Each present lobe gets at least this fraction of the largest selection weight, so that no lobe
// with a non-zero value is left unsampled when its albedo estimate is poor.
constexpr double kMinSelectionFraction = 1e-3;

// Selection probabilities from raw weights w[0..n) in place: each present lobe at least
// kMinSelectionFraction of the largest weight (all present lobes equal when every weight is 0),
// absent ones keep their weight (0), then normalised to sum 1.
void select_lobes(double* w, const bool* present, int n);

class LobeMixture {
 public:
  enum class Layer { Core, Sheen, Flake, Coat };
  static constexpr int kMaxLobes = 10;

  // The layers above the core that scale it: the clearcoat (weight c, frame with normal n_c) and
  // the sheen (ShinyCore's albedo scaling; absent without sheen).
  struct Layering {
    Frame core, coat;
    double clearcoat = 0;
    std::optional<SheenLobe> sheen;
  };

  LobeMixture() = default;
  explicit LobeMixture(Layering layering);

  // Appends a lobe of a layer (at most kMaxLobes; std::logic_error beyond).
  void add(std::unique_ptr<Lobe> lobe, Layer layer);
  int size() const { return n_; }
  Layer layer(int k) const { return entries_[size_t(k)].layer; }
  const Lobe& lobe(int k) const { return *entries_[size_t(k)].lobe; }
  const Layering& layering() const { return layering_; }

  // Raw selection weights for v (>= 0, finite), scale s included; w has size() entries.
  void selection_weights(const Vec3& v, double s, double* w) const;
  Rgb eval(const Vec3& v, const Vec3& l, double s) const;
  // Mixture density of the non-delta lobes for selection probabilities probs[0..size()).
  double pdf(const Vec3& v, const Vec3& l, const double* probs) const;
  // Samples lobe k (chosen with probability probs[k]) with u.x already rescaled to [0, 1): the
  // conventions of bsdf.h for the whole mixture.
  BsdfSample sample_lobe(int k, const Vec3& v, const Vec3& u, double s, const double* probs) const;
  uint32_t flags() const;

 private:
  // The lobe types called directly (final classes); Other: through the virtual interface.
  enum class Kind { Reflection, MultiScatter, Diffuse, Other };
  struct Entry {
    std::unique_ptr<Lobe> lobe;
    Layer layer = Layer::Core;
    Kind kind = Kind::Other;
    bool delta = false;  // lobe->is_delta(), fixed once the lobe is built
  };
  static Rgb eval_lobe(const Entry& e, const Vec3& v, const Vec3& l, LobeCache& cache);
  static double pdf_lobe(const Entry& e, const Vec3& v, const Vec3& l);
  static double weight_lobe(const Entry& e, const Vec3& v, LobeCache& cache);
  // w in the core frame (the identity frame: w itself).
  Vec3 to_core(const Vec3& w) const { return core_identity_ ? w : layering_.core.to_local(w); }
  // The layer factors for (v, l), times s.
  struct Factors {
    double core, sheen_flake, coat;
  };
  Factors factors(const Vec3& v, const Vec3& l, double s) const;
  double factor(const Factors& f, Layer layer) const;
  const Frame& frame(Layer layer) const { return layer == Layer::Coat ? layering_.coat : layering_.core; }

  Layering layering_;
  bool core_identity_ = true;  // core frame == (x, y, z)
  bool layered_ = false;       // a clearcoat or a sheen scales the layers below (else every factor is s)
  std::array<Entry, kMaxLobes> entries_;
  int n_ = 0;
};

}  // namespace dspbr
