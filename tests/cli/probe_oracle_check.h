// A probed pixel against its oracle, as the tests of real files read it from
// `shadelab probe --format json`: the rendered value within the oracle tests'
// standard bound (oracle_scene.h: 1e-4 relative, floored at 0.01), plus a
// slack of the caller's where its scene costs more (stated there).
#ifndef shadelab_probe_oracle_check_h
#define shadelab_probe_oracle_check_h

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace shadelab_test
{
inline void ExpectRenderedIsOracle(
  const nlohmann::json& probe, const std::string& where, double slack = 0)
{
  for (int c = 0; c < 3; ++c)
  {
    const double rendered = probe.at("rendered").at(c).get<double>();
    const double oracle = probe.at("oracle").at(c).get<double>();
    EXPECT_NEAR(rendered, oracle, 1e-4 * std::max(std::abs(oracle), 0.01) + slack)
      << where << ", channel " << c;
  }
}
}

#endif
