#include "dspbr/bsdf/dispersion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dspbr {

double dispersion_ior(double eta_d, double abbe_number, double lambda_nm) {
  if (!(lambda_nm > 0) || std::isinf(lambda_nm))
    throw std::invalid_argument("dispersion_ior: wavelength must be a positive number of nm, got " +
                                std::to_string(lambda_nm));
  if (!(abbe_number > 0) || std::isinf(abbe_number)) return eta_d;  // nu_d = 0: dispersion disabled
  // Spec "Dispersion": Cauchy eta = a + b / lambda^2 with b from nu_d and a from eta(d) = eta_d.
  const double eta = eta_d + (eta_d - 1.0) / abbe_number * (523655.0 / (lambda_nm * lambda_nm) - 1.5168);
  return std::max(eta, 1.0);
}

}  // namespace dspbr
