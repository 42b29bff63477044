#include "foldkit/statespaces/driving_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <utility>

#include <ompl/base/ProjectionEvaluator.h>
#include <ompl/util/Exception.h>

namespace foldkit::statespaces {

namespace ob = ompl::base;
using State = DrivingStateSpace::StateType;
using geometry::FoldState;

// A solver with the memory of the line it last interpolated along: from-state, to-driving and
// the points reached, so that interpolating further along the same line continues from the
// farthest point not past the fraction asked for.
struct DrivingStateSpace::Worker {
  Worker(const geometry::ClosureSystem& system, const geometry::DrivingChart& chart, const geometry::PassiveSolverOptions& o)
      : solver(system, chart, o) {}
  geometry::PassiveSolver solver;
  Eigen::VectorXd from, to;
  bool from_closed = false;
  std::vector<std::pair<double, FoldState>> points;
  static constexpr std::size_t kMaxPoints = 512;
};

class DrivingStateSpace::Lease {
 public:
  explicit Lease(const DrivingStateSpace& space) : space_(space), worker_(space.take()) {}
  ~Lease() { space_.give(std::move(worker_)); }
  Lease(const Lease&) = delete;
  Lease& operator=(const Lease&) = delete;
  Worker* operator->() const { return worker_.get(); }

 private:
  const DrivingStateSpace& space_;
  std::unique_ptr<Worker> worker_;
};

namespace {

// Projection for the planners that grid the space (KPIECE1, …): the first two driving angles.
class DrivingProjection : public ob::ProjectionEvaluator {
 public:
  explicit DrivingProjection(const DrivingStateSpace* space)
      : ob::ProjectionEvaluator(space), space_(space), dims_(std::min<std::size_t>(2, space->chart().driving.size())) {}
  unsigned int getDimension() const override { return static_cast<unsigned int>(dims_); }
  void defaultCellSizes() override { cellSizes_.assign(dims_, 0.1); }
  void project(const ob::State* state, Eigen::Ref<Eigen::VectorXd> projection) const override {
    const auto* s = state->as<State>();
    for (std::size_t i = 0; i < dims_; ++i) projection[static_cast<Eigen::Index>(i)] = s->angles[space_->chart().driving[i]];
  }

 private:
  const DrivingStateSpace* space_;
  std::size_t dims_;
};

Eigen::VectorXd angles_of(const State* s, std::size_t n) {
  return Eigen::Map<const Eigen::VectorXd>(s->angles, static_cast<Eigen::Index>(n));
}

}  // namespace

DrivingStateSpace::DrivingStateSpace(std::shared_ptr<const geometry::ClosureSystem> system, geometry::DrivingChart chart,
                                     AngleBounds bounds, Eigen::VectorXd driving_lower, Eigen::VectorXd driving_upper,
                                     geometry::PassiveSolverOptions options)
    : ClosedAnglesSpace("Driving", static_cast<std::size_t>(system->cols()), std::move(bounds)),
      system_(std::move(system)),
      chart_(std::move(chart)),
      driving_lower_(std::move(driving_lower)),
      driving_upper_(std::move(driving_upper)),
      options_(options) {
  type_ = ob::STATE_SPACE_TYPE_COUNT + 72;
  const auto d = static_cast<Eigen::Index>(chart_.driving.size());
  if (d == 0) throw ompl::Exception("DrivingStateSpace: the chart has no driving crease (nothing moves)");
  if (driving_lower_.size() != d || driving_upper_.size() != d || (driving_lower_.array() > driving_upper_.array()).any())
    throw ompl::Exception("DrivingStateSpace: the driving bounds do not hold one range per driving crease");
  focus_lower_ = driving_lower_;
  focus_upper_ = driving_upper_;
}

DrivingStateSpace::~DrivingStateSpace() = default;

std::unique_ptr<DrivingStateSpace::Worker> DrivingStateSpace::take() const {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!pool_.empty()) {
      auto w = std::move(pool_.back());
      pool_.pop_back();
      return w;
    }
  }
  return std::make_unique<Worker>(*system_, chart_, options_);
}

void DrivingStateSpace::give(std::unique_ptr<Worker> worker) const {
  std::lock_guard<std::mutex> lock(mutex_);
  pool_.push_back(std::move(worker));
}

bool DrivingStateSpace::add_anchor(const FoldState& state) {
  if (static_cast<std::size_t>(state.angles.size()) != n_) return false;
  FoldState corrected = state;
  Lease w(*this);
  if (!w->solver.correct(corrected) || (corrected.angles - state.angles).cwiseAbs().maxCoeff() > 1e-6) return false;
  anchor_driving_.push_back(w->solver.driving_of(corrected));
  anchors_.push_back(std::move(corrected));
  return true;
}

const FoldState* DrivingStateSpace::nearest_anchor(const Eigen::VectorXd& driving) const {
  const FoldState* best = nullptr;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < anchors_.size(); ++i) {
    const double d = (anchor_driving_[i] - driving).squaredNorm();
    if (d < best_d) {
      best_d = d;
      best = &anchors_[i];
    }
  }
  return best;
}

// A state without passives: they are set to 0 (a function of nothing but the driving angles, so
// that interpolation continued from such a state equals interpolation straight there).
void DrivingStateSpace::set_open(State* s, const Eigen::VectorXd& driving) const {
  std::fill(s->angles, s->angles + n_, 0.0);
  for (std::size_t i = 0; i < chart_.driving.size(); ++i) s->angles[chart_.driving[i]] = driving[static_cast<Eigen::Index>(i)];
  s->closed = false;
}

void DrivingStateSpace::solve(const Eigen::VectorXd& driving, const FoldState* from, ob::State* state) const {
  auto* s = state->as<State>();
  if (!from) from = nearest_anchor(driving);
  if (!from) return set_open(s, driving);
  FoldState out;
  Lease w(*this);
  if (!w->solver.follow(*from, driving, out)) return set_open(s, driving);
  std::copy(out.angles.data(), out.angles.data() + n_, s->angles);
  s->closed = true;
}

bool DrivingStateSpace::from_fold_state(const FoldState& angles, ob::State* state, double tolerance) const {
  if (static_cast<std::size_t>(angles.angles.size()) != n_) return false;
  auto* s = state->as<State>();
  FoldState corrected = angles;
  Lease w(*this);
  const bool ok = w->solver.correct(corrected) && (corrected.angles - angles.angles).cwiseAbs().maxCoeff() <= tolerance;
  std::copy(corrected.angles.data(), corrected.angles.data() + n_, s->angles);
  s->closed = ok;
  return ok;
}

FoldState DrivingStateSpace::to_fold_state(const ob::State* state) const { return FoldState{angles_of(state->as<State>(), n_)}; }

Eigen::VectorXd DrivingStateSpace::driving_of(const ob::State* state) const {
  const auto* s = state->as<State>();
  Eigen::VectorXd d(static_cast<Eigen::Index>(chart_.driving.size()));
  for (std::size_t i = 0; i < chart_.driving.size(); ++i) d[static_cast<Eigen::Index>(i)] = s->angles[chart_.driving[i]];
  return d;
}

unsigned int DrivingStateSpace::getDimension() const { return static_cast<unsigned int>(chart_.driving.size()); }

void DrivingStateSpace::set_focus(const Eigen::VectorXd& lower, const Eigen::VectorXd& upper, double share) {
  if (lower.size() != driving_lower_.size() || upper.size() != driving_lower_.size() || (lower.array() > upper.array()).any())
    throw std::invalid_argument("DrivingStateSpace::set_focus: one lower ≤ upper pair per driving crease");
  if (!(share >= 0.0 && share <= 1.0)) throw std::invalid_argument("DrivingStateSpace::set_focus: the share must be in [0, 1]");
  focus_lower_ = lower.cwiseMax(driving_lower_).cwiseMin(driving_upper_);
  focus_upper_ = upper.cwiseMax(driving_lower_).cwiseMin(driving_upper_);
  focus_share_ = share;
}

double DrivingStateSpace::getMaximumExtent() const { return (driving_upper_ - driving_lower_).norm(); }

double DrivingStateSpace::getMeasure() const { return (driving_upper_ - driving_lower_).prod(); }

void DrivingStateSpace::enforceBounds(ob::State* state) const {
  auto* s = state->as<State>();
  const Eigen::VectorXd d = driving_of(state);
  const Eigen::VectorXd clamped = d.cwiseMax(driving_lower_).cwiseMin(driving_upper_);
  if (s->closed && clamped == d) return;
  if (s->closed) {
    const FoldState here = to_fold_state(state);
    return solve(clamped, &here, state);
  }
  solve(clamped, nullptr, state);
}

bool DrivingStateSpace::satisfiesBounds(const ob::State* state) const {
  if (!ClosedAnglesSpace::satisfiesBounds(state)) return false;
  const Eigen::VectorXd d = driving_of(state);
  return (d.array() >= driving_lower_.array() - 1e-12).all() && (d.array() <= driving_upper_.array() + 1e-12).all();
}

double DrivingStateSpace::distance(const ob::State* state1, const ob::State* state2) const {
  const auto* a = state1->as<State>();
  const auto* b = state2->as<State>();
  double sum = 0.0;
  for (int j : chart_.driving) sum += (a->angles[j] - b->angles[j]) * (a->angles[j] - b->angles[j]);
  return std::sqrt(sum);
}

bool DrivingStateSpace::equalStates(const ob::State* state1, const ob::State* state2) const {
  const auto* a = state1->as<State>();
  const auto* b = state2->as<State>();
  if (a->closed != b->closed) return false;
  for (std::size_t j = 0; j < n_; ++j)
    if (std::abs(a->angles[j] - b->angles[j]) > 1e-12) return false;
  return true;
}

void DrivingStateSpace::interpolate(const ob::State* from, const ob::State* to, double t, ob::State* state) const {
  if (t <= 0.0) return copyState(state, from);
  if (t >= 1.0) return copyState(state, to);
  // Everything needed of `from` and `to` is read before `state` (which may be either) is written.
  const auto* f = from->as<State>();
  const Eigen::VectorXd fa = angles_of(f, n_), df = driving_of(from), dg = driving_of(to);
  const bool from_closed = f->closed;
  const Eigen::VectorXd target = df + t * (dg - df);
  auto* s = state->as<State>();
  Lease w(*this);
  if (w->from_closed != from_closed || w->from.size() != fa.size() || w->from != fa || w->to != dg) {
    w->from = fa;
    w->to = dg;
    w->from_closed = from_closed;
    w->points.clear();
    if (from_closed) w->points.emplace_back(0.0, FoldState{fa});
  }
  const FoldState* base = nullptr;
  double base_t = -1.0;
  for (const auto& p : w->points)
    if (p.first <= t && p.first > base_t) {
      base_t = p.first;
      base = &p.second;
    }
  if (!base) base = nearest_anchor(target);
  FoldState out;
  if (!base || !w->solver.follow(*base, target, out)) return set_open(s, target);
  std::copy(out.angles.data(), out.angles.data() + n_, s->angles);
  s->closed = true;
  if (w->points.size() >= Worker::kMaxPoints) w->points.resize(from_closed ? 1 : 0);
  w->points.emplace_back(t, std::move(out));
}

ClosedAnglesState* DrivingStateSpace::new_state() const {
  auto* s = new StateType;
  s->closed = false;
  return s;
}

ob::StateSamplerPtr DrivingStateSpace::allocDefaultStateSampler() const { return std::make_shared<DrivingSampler>(this); }

void DrivingStateSpace::printState(const ob::State* state, std::ostream& out) const {
  const auto* s = state->as<State>();
  out << "DrivingState [";
  for (std::size_t i = 0; i < chart_.driving.size(); ++i) out << (i ? " " : "") << s->angles[chart_.driving[i]];
  out << "]" << (s->closed ? "" : " (not closed)") << '\n';
}

void DrivingStateSpace::registerProjections() { registerDefaultProjection(std::make_shared<DrivingProjection>(this)); }

DrivingSampler::DrivingSampler(const DrivingStateSpace* space) : ob::StateSampler(space), space_(space) {}

template <typename Draw>
bool DrivingSampler::draw_about(ob::State* state, const ob::State* about, Draw draw) {
  FoldState base;
  const bool from_about = about && about->as<State>()->closed;
  if (from_about) base = space_->to_fold_state(about);
  for (int tries = 0; tries < kMaxTries; ++tries) {
    Eigen::VectorXd d = draw().cwiseMax(space_->driving_lower()).cwiseMin(space_->driving_upper());
    space_->solve(d, from_about ? &base : nullptr, state);
    if (space_->satisfiesBounds(state)) return true;
  }
  return false;
}

void DrivingSampler::sampleUniform(ob::State* state) {
  const bool focus = space_->focus_share() > 0.0 && rng_.uniform01() < space_->focus_share();
  const Eigen::VectorXd& lo = focus ? space_->focus_lower() : space_->driving_lower();
  const Eigen::VectorXd& hi = focus ? space_->focus_upper() : space_->driving_upper();
  draw_about(state, nullptr, [&] {
    Eigen::VectorXd d(lo.size());
    for (Eigen::Index i = 0; i < d.size(); ++i) d[i] = rng_.uniformReal(lo[i], hi[i]);
    return d;
  });
}

void DrivingSampler::sampleUniformNear(ob::State* state, const ob::State* near, double distance) {
  const Eigen::VectorXd c = space_->driving_of(near);
  const bool ok = draw_about(state, near, [&] {
    Eigen::VectorXd d(c.size());
    for (Eigen::Index i = 0; i < d.size(); ++i) d[i] = rng_.uniformReal(c[i] - distance, c[i] + distance);
    return d;
  });
  if (!ok) space_->copyState(state, near);
}

void DrivingSampler::sampleGaussian(ob::State* state, const ob::State* mean, double stdDev) {
  const Eigen::VectorXd c = space_->driving_of(mean);
  const bool ok = draw_about(state, mean, [&] {
    Eigen::VectorXd d(c.size());
    for (Eigen::Index i = 0; i < d.size(); ++i) d[i] = rng_.gaussian(c[i], stdDev);
    return d;
  });
  if (!ok) space_->copyState(state, mean);
}

StateReader driving_reader(std::shared_ptr<const DrivingStateSpace> space) { return closed_angles_reader(std::move(space)); }

}  // namespace foldkit::statespaces
