// ODE's error, debug and message handlers are process-wide: foldkit's act only inside its own
// engine calls (there an engine error becomes a report's status), and elsewhere in the process
// ODE behaves as it would without foldkit. Two threads running the engine at once each get
// their own verdict.
#include <thread>

#include <gtest/gtest.h>
#include <ode/ode.h>

#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "foldkit/geometry/generators.hpp"

using namespace foldkit;

namespace {

geometry::FoldSequence lift() {
  geometry::FoldSequence seq;
  seq.events.push_back({1, {{1, 0.5, 1.0, 0}}});
  return seq;
}

dynamics::DynamicOptions underflowing() {
  dynamics::DynamicOptions o;
  o.density = 1e-320;  // ODE refuses a body whose inertia underflows (an engine error)
  return o;
}

}  // namespace

TEST(OdeHandlers, OutsideFoldkitsCallsOdeBehavesAsWithoutFoldkit) {
  const auto p = geometry::build_or_throw(geometry::generators::strip(3));
  ASSERT_EQ(dynamics::simulate_dynamic(p, lift(), underflowing()).status.code, geometry::StatusCode::Singular);
  // foldkit's handlers are installed now; outside its calls a message is printed as ODE prints it …
  testing::internal::CaptureStderr();
  dMessage(3, "a message from %s", "elsewhere");
  EXPECT_NE(testing::internal::GetCapturedStderr().find("ODE Message 3: a message from elsewhere"), std::string::npos);
  // … and an error ends the process as ODE's default does (exit 1 after printing), not with a
  // foldkit exception escaping into code that never expected one.
  EXPECT_EXIT(dError(7, "an error from elsewhere"), testing::ExitedWithCode(1), "ODE Error 7: an error from elsewhere");
}

TEST(OdeHandlers, TwoThreadsEachGetTheirOwnVerdict) {
  const auto p = geometry::build_or_throw(geometry::generators::strip(3));
  dynamics::DynamicReport bad, good;
  std::thread a([&] {
    for (int i = 0; i < 20; ++i) bad = dynamics::simulate_dynamic(p, lift(), underflowing());
  });
  std::thread b([&] {
    for (int i = 0; i < 20; ++i) good = dynamics::simulate_dynamic(p, lift(), {});
  });
  a.join();
  b.join();
  EXPECT_EQ(bad.status.code, geometry::StatusCode::Singular) << bad.status.message;
  EXPECT_TRUE(good.status.ok()) << good.status.message;
  EXPECT_NEAR(good.final_state.angles[0], 0.5, 1e-4);
}
