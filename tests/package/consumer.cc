// Uses the installed library: a solid cube of mass 2 kg and side 0.3 m has Ixx = m·L²/6 = 0.03
// kg·m² (textbook: I = m(b² + c²)/12 for a box), and its principal moments are all equal to that.
// Through the umbrella header, so that every installed header is shown to compile on its own.
#include <cmath>
#include <iostream>

#include "massprops/massprops.h"

int main() {
  const massprops::UnitInertia<double> G = massprops::UnitInertia<double>::SolidCube(0.3);
  const massprops::RotationalInertia<double> I = 2.0 * G;
  const double expected = 2.0 * 0.3 * 0.3 / 6.0;
  const auto moments = I.CalcPrincipalMomentsOfInertia();
  for (int i = 0; i < 3; ++i) {
    if (std::abs(moments(i) - expected) > 1e-15) {
      std::cerr << "moment " << i << " = " << moments(i) << ", expected " << expected << "\n";
      return 1;
    }
  }
  std::cout << "consumer: massprops package works (Ixx = " << I(0, 0) << ")\n";
  return 0;
}
