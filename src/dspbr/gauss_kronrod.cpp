#include "dspbr/gauss_kronrod.h"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

namespace dspbr {

template <int N>
const GaussKronrod<N>& GaussKronrod<N>::get() {
  static const GaussKronrod rule = [] {
    using Kronrod = boost::math::quadrature::gauss_kronrod<double, N>;
    using Gauss = boost::math::quadrature::gauss<double, N / 2>;
    // Boost stores the non-negative half: Kronrod node i (i even: the Gauss node i / 2; n = 7
    // and 15 are odd, so node 0 = 0 is a Gauss node).
    static_assert((N / 2) % 2 == 1, "the Gauss order must be odd for this index map");
    GaussKronrod r{};
    int n = 0;
    for (size_t i = 0; i < Kronrod::abscissa().size(); ++i) {
      const double wg = i % 2 == 0 ? Gauss::weights()[i / 2] : 0.0;
      for (const double sign : {1.0, -1.0}) {
        if (i == 0 && sign < 0) continue;
        r.x[size_t(n)] = sign * Kronrod::abscissa()[i];
        r.wk[size_t(n)] = Kronrod::weights()[i];
        r.wg[size_t(n)] = wg;
        ++n;
      }
    }
    return r;
  }();
  return rule;
}

template struct GaussKronrod<15>;
template struct GaussKronrod<31>;

}  // namespace dspbr
