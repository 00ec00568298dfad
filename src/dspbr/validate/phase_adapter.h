// Runs the BSDF checks on the Henyey-Greenstein phase function (bsdf/volume.h): a Bsdf whose
// eval(v, l) |l.z| is the phase function p(v, l; g), so that the white furnace integrates
// Integral p dl = 1 (the phase function preserves energy exactly), the chi-square test checks
// hg_sample against hg_pdf, and the stability scan sweeps g. Not reciprocal as a Bsdf (the 1/|l.z|
// factor), although p itself depends only on v.l: the suite skips reciprocity for it.
#pragma once
#include <cmath>

#include "dspbr/bsdf/bsdf.h"
#include "dspbr/bsdf/volume.h"

namespace dspbr::validate {

class HgPhaseAsBsdf : public Bsdf {
 public:
  explicit HgPhaseAsBsdf(double g) : g_(g) {}
  Rgb eval(const Vec3& v, const Vec3& l) const override {
    const double c = std::abs(l.z);
    // l.z = 0 is a set of measure zero; returning 0 there avoids dividing by 0.
    return c > 0 ? Rgb(hg_phase(v, l, g_) / c) : Rgb(0.0);
  }
  double pdf(const Vec3& v, const Vec3& l) const override { return hg_pdf(v, l, g_); }
  BsdfSample sample(const Vec3& v, const Vec3& u) const override {
    const PhaseSample p = hg_sample(v, g_, u.y, u.z);
    BsdfSample s;
    s.l = p.l;
    s.pdf = p.pdf;
    s.weight = Rgb(1.0);  // p / pdf with pdf = p (exact inversion); for a delta: probability 1
    s.flags = kLobeReflection | kLobeTransmission | (p.delta ? kLobeDelta : kLobeDiffuse);
    s.valid = p.pdf > 0;
    return s;
  }
  uint32_t flags() const override { return kLobeReflection | kLobeTransmission | kLobeDiffuse; }

 private:
  double g_;
};

}  // namespace dspbr::validate
