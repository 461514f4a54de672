#include "sw/apps/bouncing_spheres.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace cdvp {

namespace {

// As in the spheres scene, only IEEE basic operations and sqrt (correctly
// rounded everywhere) are used, so a seed gives the same frames on every
// platform.

void check(bool ok, const std::string& what) {
    if (!ok) {
        throw InputError("bouncing spheres: " + what);
    }
}

void check_coefficients(double dt, double restitution) {
    check(std::isfinite(dt) && dt >= 0.0, "expected dt >= 0");
    check(restitution >= 0.0 && restitution <= 1.0, "expected restitution in [0, 1]");
}

SpheresPlacement checked_placement(const BouncingSpheresConfig& config) {
    check_coefficients(config.dt, config.restitution);
    check(config.radius_min > 0.0, "expected radius_min > 0");
    return place_spheres(config);
}

double mass(const SphereState& s) { return s.radius * s.radius * s.radius; }

}  // namespace

BouncingSpheres::BouncingSpheres(const BouncingSpheresConfig& config)
    : BouncingSpheres(checked_placement(config), config.dt, config.restitution) {}

BouncingSpheres::BouncingSpheres(SpheresPlacement start, double dt, double restitution)
    : edge_(start.edge), dt_(dt), restitution_(restitution), spheres_(std::move(start.spheres)) {
    check_coefficients(dt, restitution);
    check(std::isfinite(edge_) && edge_ > 0.0, "expected a finite edge > 0");
    // Pair indices are uint32_t.
    check(spheres_.size() <= UINT32_MAX, "too many spheres");
    for (const SphereState& s : spheres_) {
        check(std::isfinite(s.radius) && s.radius > 0.0 && 2.0 * s.radius <= edge_,
              "expected 0 < radius <= edge / 2");
        double hi = centre_limit(edge_, s.radius);
        for (int axis = 0; axis < 3; ++axis) {
            check(s.centre[axis] >= s.radius && s.centre[axis] <= hi,
                  "expected every sphere inside the cube");
            check(std::isfinite(s.velocity[axis]), "expected finite velocities");
        }
        hi_.push_back(hi);
    }
}

Frame BouncingSpheres::frame() const { return spheres_frame(number_, spheres_); }

PairList BouncingSpheres::sorted_pairs(const PairList& candidates) const {
    PairList pairs;
    pairs.reserve(candidates.size());
    for (IndexPair p : candidates) {
        if (p.first >= spheres_.size() || p.second >= spheres_.size()) {
            throw std::out_of_range("bouncing spheres: candidate pair index out of range");
        }
        if (p.first == p.second) {
            throw std::invalid_argument("bouncing spheres: candidate pair of a sphere with itself");
        }
        if (p.first > p.second) {
            std::swap(p.first, p.second);
        }
        pairs.push_back(p);
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
}

StepStats BouncingSpheres::step(const PairList& candidates) {
    StepStats stats;
    stats.candidates = candidates.size();

    // Narrow phase on the state frame() reported, before anything moves: the
    // broad phase vouched for exactly that state, and a correction below
    // could otherwise create contacts it never saw.
    std::vector<Contact> contacts;
    for (const IndexPair& p : sorted_pairs(candidates)) {
        const SphereState& a = spheres_[p.first];
        const SphereState& b = spheres_[p.second];
        std::array<double, 3> d;
        for (int axis = 0; axis < 3; ++axis) {
            d[axis] = b.centre[axis] - a.centre[axis];
        }
        double distance = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        double reach = a.radius + b.radius;
        if (distance > reach) {
            continue;
        }
        Contact c{p.first, p.second, {1.0, 0.0, 0.0}, reach - distance};
        if (distance > 0.0) {  // concentric spheres keep the fixed normal
            for (int axis = 0; axis < 3; ++axis) {
                c.normal[axis] = d[axis] / distance;
            }
        }
        contacts.push_back(c);
    }
    stats.contacts = contacts.size();

    for (const Contact& c : contacts) {
        resolve(c);
    }
    for (std::size_t k = 0; k < spheres_.size(); ++k) {
        SphereState& s = spheres_[k];
        // A correction may have pushed a sphere into a wall; put it back
        // first, or move_sphere would take that for a bounce and flip its
        // velocity.
        for (double& x : s.centre) {
            x = std::clamp(x, s.radius, hi_[k]);
        }
        move_sphere(s, hi_[k], dt_);
    }
    ++number_;
    return stats;
}

void BouncingSpheres::resolve(const Contact& c) {
    SphereState& a = spheres_[c.a];
    SphereState& b = spheres_[c.b];
    if (a.fixed && b.fixed) return;
    double ma = mass(a);
    double mb = mass(b);
    // Shares of the exchange: a moves by mb / (ma + mb), b by ma / (ma + mb),
    // which keeps the momentum and the centre of mass. A static body's mass
    // is infinite: the other takes the whole exchange.
    double share_a = a.fixed ? 0.0 : b.fixed ? 1.0 : mb / (ma + mb);
    double share_b = b.fixed ? 0.0 : a.fixed ? 1.0 : ma / (ma + mb);

    const std::array<double, 3>& n = c.normal;
    double approach = 0.0;  // normal relative velocity; < 0 when closing
    for (int axis = 0; axis < 3; ++axis) {
        approach += (b.velocity[axis] - a.velocity[axis]) * n[axis];
    }
    // Separating pairs keep their velocities, or a pair still overlapping
    // after a bounce would be pulled back together.
    if (approach < 0.0) {
        double dv = (1.0 + restitution_) * approach;
        for (int axis = 0; axis < 3; ++axis) {
            a.velocity[axis] += dv * share_a * n[axis];
            b.velocity[axis] -= dv * share_b * n[axis];
        }
    }
    // Move the pair apart until just touching; velocities are untouched, so
    // this adds no energy.
    for (int axis = 0; axis < 3; ++axis) {
        a.centre[axis] -= c.depth * share_a * n[axis];
        b.centre[axis] += c.depth * share_b * n[axis];
    }
}

double BouncingSpheres::kinetic_energy() const {
    double energy = 0.0;
    for (const SphereState& s : spheres_) {
        const std::array<double, 3>& v = s.velocity;
        energy += 0.5 * mass(s) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    return energy;
}

std::array<double, 3> BouncingSpheres::momentum() const {
    std::array<double, 3> p{0.0, 0.0, 0.0};
    for (const SphereState& s : spheres_) {
        for (int axis = 0; axis < 3; ++axis) {
            p[axis] += mass(s) * s.velocity[axis];
        }
    }
    return p;
}

}  // namespace cdvp
