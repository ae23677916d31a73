#include "io/trajectory_filter.h"

#include <algorithm>
#include <cmath>

namespace massprops::io_internal {

namespace {

struct Biquad {
  double b0, b1, b2, a1, a2;
};

// Second-order Butterworth low-pass by the bilinear transform with a prewarped cutoff.
Biquad Butterworth2(double sample_rate_hz, double cutoff_hz) {
  const double K = std::tan(M_PI * cutoff_hz / sample_rate_hz);
  const double norm = 1 / (1 + std::sqrt(2.0) * K + K * K);
  const double b0 = K * K * norm;
  return {b0, 2 * b0, b0, 2 * (K * K - 1) * norm, (1 - std::sqrt(2.0) * K + K * K) * norm};
}

// Runs the filter over x in place (direct form II transposed), starting in the steady state of
// x[0] (a constant input passes unchanged: the DC gain is 1).
void Run(const Biquad& f, Eigen::VectorXd* x) {
  const double x0 = (*x)(0);
  double z2 = (f.b2 - f.a2) * x0;
  double z1 = (f.b1 - f.a1) * x0 + z2;
  for (Eigen::Index i = 0; i < x->size(); ++i) {
    const double in = (*x)(i);
    const double out = f.b0 * in + z1;
    z1 = f.b1 * in - f.a1 * out + z2;
    z2 = f.b2 * in - f.a2 * out;
    (*x)(i) = out;
  }
}

}  // namespace

Eigen::VectorXd LowPassZeroPhase(const Eigen::VectorXd& x, double sample_rate_hz,
                                 double cutoff_hz) {
  const Eigen::Index n = x.size();
  const Eigen::Index periods = static_cast<Eigen::Index>(std::ceil(3 * sample_rate_hz / cutoff_hz));
  const Eigen::Index pad = std::min<Eigen::Index>(n - 1, std::max<Eigen::Index>(9, periods));
  // Odd reflection about each end: x[-k] = 2·x[0] − x[k], x[n−1+k] = 2·x[n−1] − x[n−1−k].
  Eigen::VectorXd y(n + 2 * pad);
  for (Eigen::Index k = 0; k < pad; ++k) {
    y(pad - 1 - k) = 2 * x(0) - x(k + 1);
    y(pad + n + k) = 2 * x(n - 1) - x(n - 2 - k);
  }
  y.segment(pad, n) = x;
  const Biquad f = Butterworth2(sample_rate_hz, cutoff_hz);
  Run(f, &y);
  y.reverseInPlace();
  Run(f, &y);
  y.reverseInPlace();
  return y.segment(pad, n);
}

Eigen::VectorXd CentralDifference(const Eigen::VectorXd& t, const Eigen::VectorXd& x) {
  const Eigen::Index n = x.size();
  Eigen::VectorXd d(n);
  d(0) = (x(1) - x(0)) / (t(1) - t(0));
  d(n - 1) = (x(n - 1) - x(n - 2)) / (t(n - 1) - t(n - 2));
  for (Eigen::Index i = 1; i + 1 < n; ++i) d(i) = (x(i + 1) - x(i - 1)) / (t(i + 1) - t(i - 1));
  return d;
}

}  // namespace massprops::io_internal
