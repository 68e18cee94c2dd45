// The diagnosis from tooth loads on a synthetic contact log of three planets meshing in phase
// with the sun: planet 0's tooth 0 carries nothing (a flank relieved past contact), and at those
// instants planets 1 and 2 carry the load planet 0 sheds. The fault is planet 0 tooth 0 alone;
// planets 1 and 2's tooth 0 (more mean load, a sound share of their mesh) are responses with
// their reason; a healthy log gives nothing.
#include <gtest/gtest.h>

#include "analysis/diagnosis.hpp"
#include "analysis/tooth_loads.hpp"

namespace gearsim {
namespace test_diagnosis {

constexpr int kTeeth = 36;
constexpr int kStepsPerTooth = 20;  // steps per mesh period
constexpr int kRevolutions = 6;
constexpr double kDt = 1e-4;

// Each planet p meshes in phase: in mesh period m its tooth m % 36 enters; for the first 60 % of
// the period the previous tooth still shares the load half and half. Mesh total 300 N/3 per
// planet; what planet 0's tooth 0 cannot carry goes to its neighbour in the mesh and, in equal
// halves, to planets 1 and 2.
ToothContactLog synthetic_log(bool faulty) {
  ToothContactLog log;
  log.pairs = {{"sun", "planet_0"}, {"sun", "planet_1"}, {"sun", "planet_2"}};
  const int steps = kTeeth * kStepsPerTooth * kRevolutions;
  for (int s = 0; s < steps; ++s) {
    const double t = s * kDt;
    const int m = s / kStepsPerTooth, in = m % kTeeth, out = (m + kTeeth - 1) % kTeeth;
    const bool shared = (s % kStepsPerTooth) < 0.6 * kStepsPerTooth;
    // Planet 0's load with tooth 0 carrying nothing; the shed load goes to planets 1 and 2.
    double planet0 = 100, shed = 0;
    std::vector<std::pair<int, double>> p0;
    if (shared)
      p0 = {{out, 50}, {in, 50}};
    else
      p0 = {{in, 100}};
    if (faulty) {
      for (auto& [tooth, f] : p0)
        if (tooth == 0) {
          // Its mesh partner takes what it can (in the shared span), the rest leaves the planet.
          if (p0.size() == 2)
            (p0[0].first == 0 ? p0[1] : p0[0]).second += f;
          else
            shed += f, planet0 -= f;
          f = 0;
        }
    }
    for (int p = 0; p < 3; ++p) {
      const double extra = p == 0 ? 0.0 : shed / 2;
      const std::vector<std::pair<int, double>> pairs =
          p == 0 ? p0
                 : (shared ? std::vector<std::pair<int, double>>{{out, 50 + extra / 2}, {in, 50 + extra / 2}}
                           : std::vector<std::pair<int, double>>{{in, 100 + extra}});
      for (const auto& [tooth, f] : pairs) {
        if (f <= 0) continue;
        log.time_s.push_back(t);
        log.pair.push_back(p);
        log.tooth_a.push_back(0);
        log.tooth_b.push_back(tooth);
        log.normal_impulse_N_s.push_back(f * kDt);
      }
    }
    (void)planet0;
  }
  return log;
}

Diagnosis diagnose(bool faulty) {
  const ToothContactLog log = synthetic_log(faulty);
  std::vector<ToothLoads> loads;
  const double end = kTeeth * kStepsPerTooth * kRevolutions * kDt;
  for (std::size_t p = 0; p < 3; ++p) loads.push_back(tooth_loads(log, p, false, kTeeth, 0.0, end, kRevolutions));
  return diagnose_from_contacts(loads, [](const PairId&, const std::string&) { return std::string("ccw"); });
}

TEST(Diagnosis, NamesTheToothThatLosesItsShareAndNoneOfItsResponders) {
  const Diagnosis d = diagnose(true);
  ASSERT_EQ(d.faults.size(), 1u);
  EXPECT_EQ(d.faults[0].gear, "planet_0");
  EXPECT_EQ(d.faults[0].tooth, 0);
  EXPECT_EQ(d.faults[0].flank, "ccw");
  EXPECT_DOUBLE_EQ(d.faults[0].confidence, 1.0);  // the least share in every revolution
  bool neighbour = false, other_planet = false;
  for (const ToothResponse& r : d.responses) {
    if (r.gear == "planet_0") {
      EXPECT_TRUE(r.tooth == 1 || r.tooth == 35) << r.tooth;
      EXPECT_NE(r.reason.find("takes up the share"), std::string::npos) << r.reason;
      neighbour = true;
    } else {
      EXPECT_EQ(r.tooth, 0) << r.gear;
      EXPECT_GT(r.load_z, 0);
      EXPECT_NE(r.reason.find("carried more load"), std::string::npos) << r.reason;
      other_planet = true;
    }
  }
  // Planet 0's neighbours of the fault take a larger share (26 steps against 20), but the fault
  // tooth's own zero widens the leave-one-out spread so that they do not stand out (z ≈ 1.8):
  // they are neither faults nor listed; when listed, the reason says why.
  (void)neighbour;
  EXPECT_TRUE(other_planet);
}

TEST(Diagnosis, AHealthyLogHasNoFaultAndNoResponse) {
  const Diagnosis d = diagnose(false);
  EXPECT_TRUE(d.faults.empty());
  EXPECT_TRUE(d.responses.empty());
}

}  // namespace test_diagnosis
}  // namespace gearsim
