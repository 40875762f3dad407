#include "jam/relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/stop.hpp"

namespace frontpack::detail {

namespace {

// FIRE's constants as Bitzek et al. give them (Table I): steps of power before dt grows, its growth
// and cut, the mixing and its decay. The time step is in units where every disk has unit mass and
// every contact unit stiffness (U = 1/2 delta^2, delta a length): a contact's period is 2 pi, a
// disk pressed by six neighbours has one of about 2.6, and 0.5 keeps the integration stable;
// lengths need no scale, so the relaxation behaves the same at any size.
constexpr std::size_t kPowerSteps = 5;
constexpr double kGrow = 1.1;
constexpr double kCut = 0.5;
constexpr double kMix = 0.1;
constexpr double kMixDecay = 0.99;
constexpr double kStep0 = 0.1;
constexpr double kStepMax = 0.5;
// The relaxation gives up when the largest overlap left has not fallen to kStall of what it was a
// window of steps before.
constexpr std::size_t kWindow = 1000;
constexpr double kStall = 0.35;

}  // namespace

Relaxation::Relaxation(const RelaxationFrame& frame) : frame_(frame) {
  wrap_.x = frame_.periodicity != Periodicity::none;
  wrap_.y = frame_.periodicity == Periodicity::xy;
  wrap_.lx = frame_.cell.xmax - frame_.cell.xmin;
  wrap_.ly = frame_.cell.ymax - frame_.cell.ymin;
  // The skin: a pair is listed when it lies within its separation plus the skin, so the lists
  // hold until some disk has moved half the skin. A step moves a disk at most a tenth of rmin.
  skin_ = 0.5 * frame_.rmin;
}

void Relaxation::build_lists(const std::vector<Disk>& disks) {
  const double reach = 2 * frame_.rmax + gap(frame_.rmax, frame_.rmax) + skin_;
  grid_.build(disks, frame_.cell, wrap_.x, wrap_.y, reach);
  pairs_.clear();
  for (std::size_t c = 0; c < grid_.cells(); ++c) {
    for (std::uint32_t a = grid_.begin(c); a < grid_.end(c); ++a) {
      const std::uint32_t i = grid_.item(a);
      const Disk& di = disks[i];
      grid_.neighbours(c, [&](std::size_t k) {
        for (std::uint32_t e = grid_.begin(k); e < grid_.end(k); ++e) {
          const std::uint32_t j = grid_.item(e);
          if (j <= i) {
            continue;
          }
          double dx = disks[j].centre.x - di.centre.x;
          double dy = disks[j].centre.y - di.centre.y;
          wrap_difference(dx, dy);
          const double g = gap(di.radius, disks[j].radius);
          const double contact = di.radius + disks[j].radius + g;
          const double s = contact + skin_;
          if (dx * dx + dy * dy < s * s) {
            pairs_.push_back({i, j, contact, g / 2});
          }
        }
      });
    }
  }
  near_wall_.clear();
  if (frame_.walls != nullptr && frame_.walls->has_walls()) {
    for (std::uint32_t i = 0; i < disks.size(); ++i) {
      const Disk& d = disks[i];
      if (frame_.walls->closer_than(d.centre, d.radius + gap(d.radius, d.radius) + skin_)) {
        near_wall_.push_back(i);
      }
    }
  }
  built_at_.resize(disks.size());
  for (std::size_t i = 0; i < disks.size(); ++i) {
    built_at_[i] = disks[i].centre;
  }
}

double Relaxation::forces(const std::vector<Disk>& disks) {
  std::fill(force_.begin(), force_.end(), Point{0, 0});
  double worst = -std::numeric_limits<double>::infinity();
  for (const Pair& p : pairs_) {
    const Disk& a = disks[p.i];
    const Disk& b = disks[p.j];
    double dx = b.centre.x - a.centre.x;
    double dy = b.centre.y - a.centre.y;
    wrap_difference(dx, dy);
    const double s = p.contact;
    const double d2 = dx * dx + dy * dy;
    if (d2 >= s * s) {
      continue;
    }
    const double d = std::sqrt(d2);
    const double delta = s - d;
    worst = std::max(worst, delta - p.half_gap);
    // Two centres at the same point (two disks inserted there) part along x.
    const double k = d > 0 ? delta / d : 0;
    const double fx = d > 0 ? k * dx : delta;
    const double fy = k * dy;
    force_[p.j].x += fx;
    force_[p.j].y += fy;
    force_[p.i].x -= fx;
    force_[p.i].y -= fy;
  }
  for (const std::uint32_t i : near_wall_) {
    const Disk& a = disks[i];
    const double g = gap(a.radius, a.radius);
    frame_.walls->near(a.centre, a.radius + g, [&](Point q, double dist) {
      const double delta = a.radius + g - dist;
      if (delta <= 0 || dist <= 0) {
        return;
      }
      worst = std::max(worst, delta - g / 2);
      const double k = delta / dist;
      force_[i].x += k * (a.centre.x - q.x);
      force_[i].y += k * (a.centre.y - q.y);
    });
  }
  return worst;
}

void Relaxation::fire_update(Fire& fire) const {
  double power = 0;
  double vv = 0;
  double ff = 0;
  for (std::size_t i = 0; i < force_.size(); ++i) {
    power += force_[i].x * velocity_[i].x + force_[i].y * velocity_[i].y;
    vv += velocity_[i].x * velocity_[i].x + velocity_[i].y * velocity_[i].y;
    ff += force_[i].x * force_[i].x + force_[i].y * force_[i].y;
  }
  fire.mixing = power > 0;
  fire.scale = fire.mixing && ff > 0 ? fire.mix * std::sqrt(vv / ff) : 0;
  fire.keep = 1 - fire.mix;
  if (fire.mixing) {
    if (++fire.power_steps > kPowerSteps) {
      fire.dt = std::min(fire.dt * kGrow, kStepMax);
      fire.mix *= kMixDecay;
    }
  } else {
    fire.dt *= kCut;
    fire.mix = kMix;
    fire.power_steps = 0;
  }
}

bool Relaxation::move_disks(std::vector<Disk>& disks, const Fire& fire, double max_step, double rebuild2) {
  const Box& cell = frame_.cell;
  const double dt = fire.dt;
  bool rebuild = false;
  for (std::size_t i = 0; i < disks.size(); ++i) {
    Point& v = velocity_[i];
    if (fire.mixing) {
      v.x = fire.keep * v.x + fire.scale * force_[i].x;
      v.y = fire.keep * v.y + fire.scale * force_[i].y;
    } else {
      v = Point{0, 0};
    }
    v.x += dt * force_[i].x;
    v.y += dt * force_[i].y;
    double sx = dt * v.x;
    double sy = dt * v.y;
    const double step2 = sx * sx + sy * sy;
    if (step2 > max_step * max_step) {
      // No disk jumps through a neighbour or a wall in one step.
      const double k = max_step / std::sqrt(step2);
      v.x *= k;
      v.y *= k;
      sx *= k;
      sy *= k;
    }
    Point& c = disks[i].centre;
    c.x += sx;
    c.y += sy;
    c = wrap_.into_cell(c, cell);  // (kept in the cell on a periodic axis)
    double mx = c.x - built_at_[i].x;
    double my = c.y - built_at_[i].y;
    wrap_difference(mx, my);
    rebuild = rebuild || mx * mx + my * my > rebuild2;
  }
  return rebuild;
}

bool Relaxation::run(std::vector<Disk>& disks, std::size_t max_iterations, const std::function<bool()>& keep_going,
                     const std::stop_token& stop) {
  const std::size_t n = disks.size();
  force_.assign(n, Point{0, 0});
  velocity_.assign(n, Point{0, 0});
  build_lists(disks);
  Fire fire{kStep0, kMix};
  const double max_step = 0.1 * frame_.rmin;
  const double rebuild2 = 0.25 * skin_ * skin_;
  double last_window = 0;
  for (iterations_ = 0; iterations_ < max_iterations; ++iterations_) {
    throw_if_stopped(stop);
    if (iterations_ % 64 == 63 && keep_going && !keep_going()) {
      return false;
    }
    const double w = forces(disks);
    if (w <= 0) {
      return true;
    }
    if (iterations_ % kWindow == 0) {
      // A round the packing can take sheds its overlaps geometrically, by 5-50 times per window
      // near jamming; one it cannot take stalls at overlaps of about 1e-3 rmax, each window
      // shaving off less than half (docs/jam.md).
      if (iterations_ >= 2 * kWindow && w > kStall * last_window) {
        return false;
      }
      last_window = w;
    }
    // FIRE's mixing of the velocities (with this step's mix), then its new time step and mix; the
    // move mixes each velocity and moves its disk with that time step.
    fire_update(fire);
    if (move_disks(disks, fire, max_step, rebuild2)) {
      build_lists(disks);
    }
  }
  return forces(disks) <= 0;
}

}  // namespace frontpack::detail
