// The sizing fields of the dissertation's Table 7.1 on the bundled pipe (pdd::pipe_domain: a
// unit circle with 9 holes of radius 0.12, the inner one at the origin), as expressions:
// d = distance from the inner hole (0 <= d <= 0.88 in the domain), F = scale * (a + d)^p with
// a = 0.88 / 28, so max F / min F = 29^p: 1/29, 1/841, 1/707281 for p = 1, 2, 4 (the thesis'
// global gradations); f_s = scale * rho^3 with rho the distance from the nearest hole centre
// (0.12 <= rho <= 0.5: gradation about 1/72, the thesis' 1/77).
#pragma once

#include <sstream>
#include <string>

namespace pdd::test {

inline std::string exact(double v) {
  std::ostringstream o;
  o.precision(17);
  o << v;
  return o.str();
}

inline std::string pipe_distance_field(int power, double scale) {
  return exact(scale) + "*(0.88/28+max(0,sqrt(x^2+y^2)-0.12))^" + std::to_string(power);
}

inline std::string pipe_sources_field(double scale) {
  std::string rho = "min(";
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      rho += (rho.size() > 4 ? "," : "") + std::string("(x-(") + std::to_string(0.5 * i) +
             "))^2+(y-(" + std::to_string(0.5 * j) + "))^2";
  return exact(scale) + "*(" + rho + "))^1.5";
}

} // namespace pdd::test
