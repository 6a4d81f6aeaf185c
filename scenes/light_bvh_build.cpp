#include "scenes/light_bvh_build.h"

#include <algorithm>
#include <cmath>

namespace tr {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kBuckets = 12;

// Float bounds of a double value on the safe side: the node may only grow by rounding.
float round_down(double x) {
  float f = float(x);
  return double(f) > x ? std::nextafter(f, -INFINITY) : f;
}
float round_up(double x) {
  float f = float(x);
  return double(f) < x ? std::nextafter(f, INFINITY) : f;
}

struct Bounds {
  double phi = 0.0;
  glm::dvec3 lo{INFINITY}, hi{-INFINITY};
  DirectionCone normals;
  double cos_theta_e = 1.0;

  void add(const LightBounds& l, double power) {
    phi += power;
    lo = glm::min(lo, l.lo);
    hi = glm::max(hi, l.hi);
    normals = cone_union(normals, l.normals);
    cos_theta_e = std::min(cos_theta_e, l.cos_theta_e);
  }
  void add(const Bounds& b) {
    phi += b.phi;
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
    normals = cone_union(normals, b.normals);
    cos_theta_e = std::min(cos_theta_e, b.cos_theta_e);
  }
  double surface_area() const {
    glm::dvec3 d = hi - lo;
    return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

// The orientation measure M_Omega of Conty Estevez & Kulla 2018, eq. 1 (pbrt-v4's EvaluateCost):
// the solid angle of the normal cone plus the cosine-weighted spread of the emission beyond it.
double orientation_measure(const Bounds& b) {
  const double theta_o = std::acos(std::clamp(b.normals.cos_theta, -1.0, 1.0));
  const double theta_e = std::acos(std::clamp(b.cos_theta_e, -1.0, 1.0));
  const double theta_w = std::min(theta_o + theta_e, kPi);
  const double sin_o = std::sin(theta_o);
  return 2.0 * kPi * (1.0 - std::cos(theta_o)) +
         0.5 * kPi *
             (2.0 * theta_w * sin_o - std::cos(theta_o - 2.0 * theta_w) - 2.0 * theta_o * sin_o +
              std::cos(theta_o));
}

// Eq. 2: power times orientation times area, scaled by how thin the node is along the axis.
double split_cost(const Bounds& b, const Bounds& node, int axis) {
  if (b.phi == 0.0) return 0.0;
  const glm::dvec3 d = node.hi - node.lo;
  const double k_r = std::max({d.x, d.y, d.z}) / d[axis];
  return b.phi * orientation_measure(b) * k_r * b.surface_area();
}

LightNode to_node(const Bounds& b) {
  LightNode n{};
  // The sphere around the float centre that holds every corner of the box.
  n.centre = vec3(0.5 * (b.lo + b.hi));
  const glm::dvec3 c(n.centre);
  const glm::dvec3 far = glm::max(glm::abs(b.lo - c), glm::abs(b.hi - c));
  n.radius = round_up(glm::length(far));
  n.phi = float(b.phi);
  n.w = vec3(b.normals.w);
  // Rounded to the side of the wider cone: cos theta_o down; sin theta_o up, which raises the
  // cosine of theta_w - theta_o that the importance takes outside the cone.
  const double theta_o = std::acos(std::clamp(b.normals.cos_theta, -1.0, 1.0));
  n.cos_theta_o = std::max(round_down(b.normals.cos_theta), -1.0f);
  n.sin_theta_o = std::min(round_up(std::sin(theta_o)), 1.0f);
  n.cos_theta_e = std::max(round_down(b.cos_theta_e), -1.0f);
  n.first_child = n.emitter = n.parent = NO_INDEX;
  n.child_count = 0;
  return n;
}

// A node of the binary tree the splits make, before it is collapsed to LIGHT_BVH_WIDTH.
struct BinaryNode {
  Bounds bounds;
  uint child[2] = {NO_INDEX, NO_INDEX};
  uint emitter = NO_INDEX;
};

struct Builder {
  const std::vector<LightBounds>& bounds;
  const std::vector<double>& phi;
  std::vector<BinaryNode> binary;

  glm::dvec3 centre(uint i) const { return 0.5 * (bounds[i].lo + bounds[i].hi); }

  // Appends the binary subtree over [begin, end) and returns its root.
  uint build(std::vector<uint>::iterator begin, std::vector<uint>::iterator end) {
    const uint index = uint(binary.size());
    binary.emplace_back();
    if (end - begin == 1) {
      binary[index].bounds.add(bounds[*begin], phi[*begin]);
      binary[index].emitter = *begin;
      return index;
    }
    Bounds node;
    glm::dvec3 c_lo(INFINITY), c_hi(-INFINITY);
    for (auto it = begin; it != end; ++it) {
      node.add(bounds[*it], phi[*it]);
      c_lo = glm::min(c_lo, centre(*it));
      c_hi = glm::max(c_hi, centre(*it));
    }
    double best_cost = INFINITY;
    int best_axis = -1, best_split = -1;
    for (int axis = 0; axis < 3; ++axis) {
      const double extent = c_hi[axis] - c_lo[axis];
      if (!(extent > 0.0)) continue;
      Bounds bucket[kBuckets];
      for (auto it = begin; it != end; ++it)
        bucket[bucket_of(*it, axis, c_lo[axis], extent)].add(bounds[*it], phi[*it]);
      for (int split = 0; split < kBuckets - 1; ++split) {
        Bounds below, above;
        for (int k = 0; k <= split; ++k) below.add(bucket[k]);
        for (int k = split + 1; k < kBuckets; ++k) above.add(bucket[k]);
        const double cost = split_cost(below, node, axis) + split_cost(above, node, axis);
        if (cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_split = split;
        }
      }
    }
    auto mid = begin + (end - begin) / 2;
    if (best_axis >= 0) {
      const double lo = c_lo[best_axis], extent = c_hi[best_axis] - lo;
      auto part = std::partition(
          begin, end, [&](uint i) { return bucket_of(i, best_axis, lo, extent) <= best_split; });
      if (part != begin && part != end) mid = part;
    }
    binary[index].bounds = node;
    const uint c0 = build(begin, mid);
    const uint c1 = build(mid, end);
    binary[index].child[0] = c0;
    binary[index].child[1] = c1;
    return index;
  }

  int bucket_of(uint i, int axis, double lo, double extent) const {
    int k = int(kBuckets * (centre(i)[axis] - lo) / extent);
    return std::clamp(k, 0, kBuckets - 1);
  }
};

// Lays the binary tree out as core/light_bvh.h reads it: each interior node takes up to
// LIGHT_BVH_WIDTH of its binary descendants as children, opening the most powerful interior one
// until the group is full (a wide node stands for a binary subtree's top levels, as in Wald et
// al., "Getting Rid of Packets", RT 2008), its group appended before the groups below it.
struct Collapser {
  const std::vector<BinaryNode>& binary;
  std::vector<LightNode>& nodes;
  std::vector<uint>& leaves;

  // Fills in the node at `index`, already appended for binary node `b`, and everything below.
  void lay_out(uint b, uint index) {
    const BinaryNode& node = binary[b];
    if (node.emitter != NO_INDEX) {
      nodes[index].emitter = node.emitter;
      leaves[node.emitter] = index;
      return;
    }
    std::vector<uint> group{node.child[0], node.child[1]};
    while (group.size() < LIGHT_BVH_WIDTH) {
      auto open = group.end();
      for (auto it = group.begin(); it != group.end(); ++it)
        if (binary[*it].emitter == NO_INDEX &&
            (open == group.end() || binary[*it].bounds.phi > binary[*open].bounds.phi))
          open = it;
      if (open == group.end()) break;
      const uint opened = *open;
      *open = binary[opened].child[1];
      group.insert(open, binary[opened].child[0]);
    }
    const uint first = uint(nodes.size());
    for (uint c : group) {
      nodes.push_back(to_node(binary[c].bounds));
      nodes.back().parent = index;
    }
    nodes[index].first_child = first;
    nodes[index].child_count = uint(group.size());
    for (uint k = 0; k < group.size(); ++k) lay_out(group[k], first + k);
  }
};

}  // namespace

uint build_light_bvh(const std::vector<LightBounds>& bounds, const std::vector<double>& phi,
                     std::vector<uint> members, std::vector<LightNode>& nodes,
                     std::vector<uint>& leaves) {
  nodes.clear();
  leaves.assign(bounds.size(), NO_INDEX);
  if (members.empty()) return NO_INDEX;
  Builder builder{bounds, phi, {}};
  builder.binary.reserve(2 * members.size() - 1);
  const uint root = builder.build(members.begin(), members.end());
  nodes.push_back(to_node(builder.binary[root].bounds));
  Collapser{builder.binary, nodes, leaves}.lay_out(root, 0);
  return 0;
}

}  // namespace tr
