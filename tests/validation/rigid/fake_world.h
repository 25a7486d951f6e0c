#pragma once
// A RigidWorld without an engine, for testing the shared rigid layer: its
// kinetic energy decays by a fixed factor per step, grains stay put (or one
// is thrown out when asked), and it records the object poses it was given.

#include <memory>
#include <vector>

#include "validation/rigid/rigid_engine.h"

namespace repose::test_support {

struct FakeWorldLog {
  std::vector<std::vector<Pose>> poses;  // per step
};

class FakeWorld final : public RigidWorld {
 public:
  FakeWorld(const RigidWorldSpec& spec, double decay, bool lose_one, FakeWorldLog* log)
      : grains_(spec.grains), objects_(spec.objects.size()), decay_(decay), lose_one_(lose_one), log_(log) {}
  void set_object_poses(const std::vector<Pose>& p) override {
    if (log_) log_->poses.push_back(p);
  }
  void step() override {
    energy_ *= decay_;
    if (lose_one_ && grains_.size() > 0) grains_.position_m(0, 2) = -1.0;
  }
  double time_step_s() const override { return 0.01; }
  GrainSet grains() const override { return grains_; }
  double kinetic_energy_j() const override { return energy_; }
  std::vector<Eigen::Vector3d> object_forces_n() const override {
    return std::vector<Eigen::Vector3d>(objects_, Eigen::Vector3d::Zero());
  }

 private:
  GrainSet grains_;
  std::size_t objects_;
  double energy_ = 1.0;
  double decay_;
  bool lose_one_;
  FakeWorldLog* log_;
};

inline RigidEngine fake_engine(double decay, bool lose_one = false, FakeWorldLog* log = nullptr) {
  RigidEngine e;
  e.name = "fake";
  e.version = "fake 1";
  e.options_text = "decay=" + std::to_string(decay) + "\n";
  e.rigid.time_step_s = 0.01;
  e.rigid.settle_rms_speed_m_s = 0.0;  // the dem section's threshold
  e.rigid.max_settle_time_s = 1.0;
  e.make_world = [=](const RigidWorldSpec& spec) { return std::make_unique<FakeWorld>(spec, decay, lose_one, log); };
  return e;
}

}  // namespace repose::test_support
