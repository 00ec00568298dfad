// AlbedoSlice (a table cut at fixed roughness / f0 / alpha_b / ior) against the full LutSet lookups it
// replaces in the lobes, for both layouts: the same interpolant, so equal to rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "dspbr/tables/albedo_slice.h"
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

// The E_m parts at two cosines side by side (the packed warp of tables/warped_table.h) are bit for bit
// the scalar e_m_part of each, over the domain and outside it (clamped), in both layouts.
TEST(AlbedoSlice, PairedEmPartsEqualSingleOnes) {
  for (const LutSet* luts : {&LutSet::builtin(), &LutSet::published()}) {
    Pcg32 rng(5, 0);
    for (int i = 0; i < 40; ++i) {
      const double r = i == 0 ? 0.0 : i == 1 ? 1.0 : rng.next_double();
      for (const AlbedoSlice& slice : {AlbedoSlice::E_m(*luts, r), AlbedoSlice::E_base(*luts, r, 0.04)}) {
        const double special[] = {0.0, 1.0, 1e-300, 1e-8, -0.25, 1.5, std::nan("")};
        for (int k = 0; k < 60; ++k) {
          const double a = k < 7 ? special[k] : rng.next_double(), b = k < 7 ? rng.next_double() : special[k % 7];
          AlbedoSlice::EmPart pair[2];
          slice.e_m_parts(a, b, pair);
          const AlbedoSlice::EmPart one[2] = {slice.e_m_part(a), slice.e_m_part(b)};
          for (int j = 0; j < 2; ++j) {
            EXPECT_EQ(pair[j].x, one[j].x) << r << " " << a << " " << b;
            EXPECT_EQ(pair[j].e_m, one[j].e_m) << r << " " << a << " " << b;
          }
        }
      }
    }
  }
}

// The glass slices (E_g at fixed roughness and ior; the renderer layout's ior coordinate depends
// on mu, so its slice keeps the ior rows its lookups reach) against LutSet::E_glass, both layouts
// and both sides, over the whole domain (ior 1 to beyond the tables' 3, r 0 to 1, mu 0 to 1).
TEST(AlbedoSlice, GlassSlicesEqualTheFullLookups) {
  for (const LutSet* luts : {&LutSet::builtin(), &LutSet::published()}) {
    ASSERT_TRUE(luts->has_glass());
    Pcg32 rng(7, 1);
    double worst = 0;
    for (int i = 0; i < 40; ++i) {
      const double r = i == 0 ? 0.0 : i == 1 ? 1.0 : rng.next_double();
      const double ior = i == 2 ? 1.0 : i == 3 ? 3.0 : i == 4 ? 3.5 : i % 3 == 0 ? 1.0 + 0.05 * rng.next_double()
                                                                               : 1.0 + 2.0 * rng.next_double();
      for (const bool inside : {false, true}) {
        const AlbedoSlice g = AlbedoSlice::E_glass(*luts, r, ior, inside);
        for (int k = 0; k < 50; ++k) {
          const double mu = k == 0 ? 0.0 : k == 1 ? 1.0 : k == 2 ? 1e-7 : k % 3 == 0 ? std::pow(rng.next_double(), 4)
                                                                                     : rng.next_double();
          const double full = luts->E_glass(mu, r, ior, inside);
          worst = std::max(worst, std::abs(g(mu) - full));
          EXPECT_NEAR(g(mu), full, 1e-12) << lut_layout_name(luts->layout) << " r " << r << " ior " << ior << " inside "
                                          << inside << " mu " << mu;
        }
      }
    }
    std::printf("Glass slices, %s layout: max |slice - full lookup| %.1e\n", lut_layout_name(luts->layout), worst);
  }
}

TEST(AlbedoSlice, GlassSliceNeedsGlassTables) {
  LutSet none = LutSet::builtin();
  none.renderer.glass_E = WarpedTable{};
  ASSERT_FALSE(none.has_glass());
  EXPECT_THROW(AlbedoSlice::E_glass(none, 0.5, 1.5, false), std::runtime_error);
}
