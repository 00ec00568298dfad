#include "dspbr/gauss_kronrod.h"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

namespace dspbr {

const GaussKronrod15& GaussKronrod15::get() {
  static const GaussKronrod15 rule = [] {
    using Kronrod = boost::math::quadrature::gauss_kronrod<double, 15>;
    using Gauss = boost::math::quadrature::gauss<double, 7>;
    // Boost stores the non-negative half: Kronrod node i (i even: the Gauss node i / 2).
    GaussKronrod15 r{};
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

}  // namespace dspbr
