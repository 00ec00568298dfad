#include "dspbr/bsdf/lobe_mixture.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dspbr/bsdf/cosine_factor.h"
#include "dspbr/bsdf/diffuse.h"
#include "dspbr/bsdf/microfacet_reflection.h"
#include "dspbr/bsdf/multiscatter.h"

namespace dspbr {

void select_lobes(double* w, const bool* present, int n) {
  double max_w = 0;
  for (int k = 0; k < n; ++k) max_w = std::max(max_w, w[k]);
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    if (present[k]) w[k] = max_w > 0 ? std::max(w[k], kMinSelectionFraction * max_w) : 1.0;
    sum += w[k];
  }
  if (sum > 0)
    for (int k = 0; k < n; ++k) w[k] /= sum;
}

LobeMixture::LobeMixture(Layering layering) : layering_(std::move(layering)) {
  const Frame& f = layering_.core;
  layered_ = layering_.clearcoat > 0 || layering_.sheen.has_value();
  core_identity_ = f.t.x == 1 && f.t.y == 0 && f.t.z == 0 && f.b.x == 0 && f.b.y == 1 && f.b.z == 0 && f.n.x == 0 &&
                   f.n.y == 0 && f.n.z == 1;
}

void LobeMixture::add(std::unique_ptr<Lobe> lobe, Layer layer) {
  if (n_ == kMaxLobes) throw std::logic_error("LobeMixture: more than kMaxLobes lobes");
  Kind kind = Kind::Other;
  if (dynamic_cast<const MicrofacetReflection*>(lobe.get())) kind = Kind::Reflection;
  else if (dynamic_cast<const MultiScatterReflection*>(lobe.get())) kind = Kind::MultiScatter;
  else if (dynamic_cast<const DiffuseBase*>(lobe.get())) kind = Kind::Diffuse;
  const bool delta = lobe->is_delta();
  entries_[size_t(n_++)] = {std::move(lobe), layer, kind, delta};
}

namespace {

bool on_horizon(const Vec3& w) { return !(std::abs(w.z) >= kHorizonCos); }  // NaN included

}  // namespace

Rgb LobeMixture::eval_lobe(const Entry& e, const Vec3& v, const Vec3& l, LobeCache& cache) {
  switch (e.kind) {
    case Kind::Reflection: return static_cast<const MicrofacetReflection&>(*e.lobe).eval(v, l);
    case Kind::MultiScatter: return static_cast<const MultiScatterReflection&>(*e.lobe).eval(v, l, cache);
    case Kind::Diffuse: return static_cast<const DiffuseBase&>(*e.lobe).eval(v, l, cache);
    case Kind::Other: break;
  }
  return e.lobe->eval(v, l, cache);
}

double LobeMixture::pdf_lobe(const Entry& e, const Vec3& v, const Vec3& l) {
  switch (e.kind) {
    case Kind::Reflection: return static_cast<const MicrofacetReflection&>(*e.lobe).pdf(v, l);
    case Kind::MultiScatter: return static_cast<const MultiScatterReflection&>(*e.lobe).pdf(v, l);
    case Kind::Diffuse: return static_cast<const DiffuseBase&>(*e.lobe).pdf(v, l);
    case Kind::Other: break;
  }
  return e.lobe->pdf(v, l);
}

double LobeMixture::weight_lobe(const Entry& e, const Vec3& v, LobeCache& cache) {
  switch (e.kind) {
    case Kind::Reflection: return static_cast<const MicrofacetReflection&>(*e.lobe).sampling_weight(v);
    case Kind::MultiScatter: return static_cast<const MultiScatterReflection&>(*e.lobe).sampling_weight(v, cache);
    case Kind::Diffuse: return static_cast<const DiffuseBase&>(*e.lobe).sampling_weight(v, cache);
    case Kind::Other: break;
  }
  return e.lobe->sampling_weight(v, cache);
}

LobeMixture::Factors LobeMixture::factors(const Vec3& v, const Vec3& l, double s) const {
  Factors f;
  f.coat = s;
  double below = s;
  if (layering_.clearcoat > 0) {
    // Coated: GlitteryCore (1 - c max(F_c(v.n_c), F_c(l.n_c))); |cos| for a transmitted l.
    const Vec3& nc = layering_.coat.n;
    below *= 1.0 - layering_.clearcoat * std::max(fresnel_clearcoat(dot(v, nc)), fresnel_clearcoat(dot(l, nc)));
  }
  f.sheen_flake = below;
  const Vec3& n = layering_.core.n;
  f.core = layering_.sheen ? below * layering_.sheen->layer_scale(dot(v, n), dot(l, n)) : below;
  return f;
}

double LobeMixture::factor(const Factors& f, Layer layer) const {
  switch (layer) {
    case Layer::Core: return f.core;
    case Layer::Sheen:
    case Layer::Flake: return f.sheen_flake;
    case Layer::Coat: return f.coat;
  }
  return 0;
}

void LobeMixture::selection_weights(const Vec3& v, double s, double* w) const {
  const Factors f = factors(v, v, s);
  const Vec3 v_core = to_core(v);
  LobeCache cache;
  for (int k = 0; k < n_; ++k) {
    const Entry& e = entries_[size_t(k)];
    const Vec3 vk = e.layer == Layer::Coat ? layering_.coat.to_local(v) : v_core;
    const double wk = weight_lobe(e, vk, cache) * factor(f, e.layer);
    w[k] = std::isfinite(wk) ? std::max(wk, 0.0) : 0.0;
  }
}

Rgb LobeMixture::eval(const Vec3& v, const Vec3& l, double s) const {
  Rgb sum(0);
  const Vec3 v_core = to_core(v), l_core = to_core(l);
  if (on_horizon(v_core) || on_horizon(l_core)) return sum;
  std::optional<Factors> f;  // computed at the first lobe with a non-zero value
  LobeCache cache;
  for (int k = 0; k < n_; ++k) {
    const Entry& e = entries_[size_t(k)];
    if (e.delta) continue;
    Rgb fk;
    if (e.layer == Layer::Coat) {
      // The coat reflects: nothing towards the other side of the surface (its own normal n_c may
      // differ from n; without this check f(v, l) != f(l, v) where the two planes disagree).
      if (!(l_core.z > 0)) continue;
      const Vec3 v_coat = layering_.coat.to_local(v), l_coat = layering_.coat.to_local(l);
      if (on_horizon(v_coat) || on_horizon(l_coat)) continue;
      fk = eval_lobe(e, v_coat, l_coat, cache);
    } else {
      fk = eval_lobe(e, v_core, l_core, cache);
    }
    if (!layered_) {
      sum += fk * s;  // every layer factor is s (fk is finite and >= 0: +0 for a zero value)
    } else if (fk.max_component() > 0) {
      if (!f) f = factors(v, l, s);
      sum += fk * factor(*f, e.layer);
    }
  }
  return sum;
}

double LobeMixture::pdf(const Vec3& v, const Vec3& l, const double* probs) const {
  double p = 0;
  const Vec3 v_core = to_core(v), l_core = to_core(l);
  if (on_horizon(v_core) || on_horizon(l_core)) return p;
  for (int k = 0; k < n_; ++k) {
    const Entry& e = entries_[size_t(k)];
    if (e.delta || probs[k] == 0) continue;
    if (e.layer == Layer::Coat) {
      const Vec3 v_coat = layering_.coat.to_local(v), l_coat = layering_.coat.to_local(l);
      if (!on_horizon(v_coat) && !on_horizon(l_coat)) p += probs[k] * pdf_lobe(e, v_coat, l_coat);
    } else {
      p += probs[k] * pdf_lobe(e, v_core, l_core);
    }
  }
  return p;
}

BsdfSample LobeMixture::sample_lobe(int k, const Vec3& v, const Vec3& u, double s, const double* probs) const {
  BsdfSample out;
  const Entry& e = entries_[size_t(k)];
  const Frame& fr = frame(e.layer);
  const Vec3 v_local = fr.to_local(v);
  if (on_horizon(v_local) || on_horizon(to_core(v))) return out;
  const BsdfSample ls = e.lobe->sample(v_local, u);
  if (!ls.valid) return out;
  const Vec3 l = normalize(fr.to_world(ls.l));
  if (ls.flags & kLobeDelta) {
    if (e.layer == Layer::Coat && !(dot(l, layering_.core.n) > 0)) return out;  // as in eval
    out.weight = ls.weight * (factor(factors(v, l, s), e.layer) / probs[k]);
    out.pdf = probs[k] * ls.pdf;
    out.flags = kLobeDelta | (l.z * v.z >= 0 ? kLobeReflection : kLobeTransmission);
  } else {
    out.pdf = pdf(v, l, probs);
    if (!(out.pdf > 0)) return out;
    out.weight = eval(v, l, s) * (std::abs(l.z) / out.pdf);
    out.flags = (ls.flags & (kLobeGlossy | kLobeDiffuse)) | (l.z * v.z >= 0 ? kLobeReflection : kLobeTransmission);
  }
  out.l = l;
  out.valid = true;
  return out;
}

uint32_t LobeMixture::flags() const {
  uint32_t f = 0;
  for (int k = 0; k < n_; ++k) f |= entries_[size_t(k)].lobe->flags();
  return f;
}

}  // namespace dspbr
