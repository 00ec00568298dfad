// AlbedoSlice (a table cut at fixed roughness / f0 / alpha_b) against the full LutSet lookups it
// replaces in the lobes, for both layouts: the same interpolant, so equal to rounding.
#include <gtest/gtest.h>

#include "dspbr/lut/albedo_slice.h"
#include "dspbr/rng.h"

using namespace dspbr;

TEST(AlbedoSlice, EqualsTheFullLookups) {
  for (const LutSet* luts : {&LutSet::builtin(), &LutSet::published()}) {
    Pcg32 rng(3, 0);
    for (int i = 0; i < 60; ++i) {
      const double r = i == 0 ? 0.0 : i == 1 ? 1.0 : rng.next_double();
      const double f0 = rng.next_double(), alpha_b = 1.0 / 256 + rng.next_double() * (1 - 1.0 / 256);
      const AlbedoSlice e_m = AlbedoSlice::E_m(*luts, r), e_base = AlbedoSlice::E_base(*luts, r, f0);
      const AlbedoSlice sheen = AlbedoSlice::E_sheen(*luts, alpha_b, false);
      const AlbedoSlice ash = AlbedoSlice::E_sheen(*luts, alpha_b, true);
      for (int k = 0; k < 40; ++k) {
        const double mu = k == 0 ? 0.0 : k == 1 ? 1.0 : k == 2 ? 1e-4 : rng.next_double();
        EXPECT_NEAR(e_m(mu), luts->E_m(mu, r), 1e-12) << r << " " << mu;
        EXPECT_NEAR(e_base(mu), luts->E_base(mu, r, f0), 1e-12) << r << " " << f0 << " " << mu;
        EXPECT_NEAR(sheen(mu), luts->E_sheen(mu, alpha_b), 1e-12) << alpha_b << " " << mu;
        EXPECT_NEAR(ash(mu), luts->E_sheen_ash(mu, alpha_b), 1e-12) << alpha_b << " " << mu;
      }
    }
  }
}
