// Droplet motion that seed 000's particle erosion and its flow map share (digest 000 Appendix A), CPU reference.
//
// accelerate_axis(velocity, height, ahead, behind, acceleration, max_jump) -> the new velocity component:
//   Algorithm 4 as upstream nests it, the component along an axis accelerated towards the lower side
//   along the motion (from rest the negative side); no acceleration when that drop exceeds `max_jump`
//   (the flow map passes the largest Real: no limit).
// corners_around(pos_x, pos_y) -> Corners: erode4's 4 texel centres around a droplet with their
//   bilinear weights: the corner cell ivec2(pos - 0.5) by truncation (as upstream, so within half a
//   texel of x = 0 or y = 0 the weights leave [0, 1]), then +x, +y, +xy, with the weights
//   (1-fx)(1-fy), fx(1-fy), (1-fx)fy, fx·fy.
//
// Inputs:  a droplet's velocity component and position; `ahead` and `behind` the neighbours' heights
//          at +1 and -1 along the axis.
// Outputs: the velocity component; the four texels and their weights.
// Units:   positions in texels; heights in the caller's units.
// Throws:  nothing.
// Twin:    gpu/shaders/erosion/hydra_motion.glsl (included by particle_block.glsl and flow_map_block.glsl);
//          the users: reference/erosion/particle.cpp and reference/erosion/flow_map.cpp.
#pragma once

namespace gt::reference {

struct Texel {
  int x;
  int y;
};

// Algorithm 4 as upstream nests it: the velocity component `velocity` along an axis, accelerated
// towards the lower side along the motion (from rest the negative side): `ahead` and `behind` are
// the neighbours at +1 and -1 along the axis. No acceleration when that drop exceeds `max_jump`
// (the flow map passes the largest Real: no limit).
template <class Real>
Real accelerate_axis(Real velocity, Real height, Real ahead, Real behind, Real acceleration, Real max_jump) {
  if (velocity > 0) {
    const Real drop = height - ahead;
    if (drop <= max_jump) velocity = velocity + acceleration * drop;
  } else {
    const Real drop = height - behind;
    if (drop <= max_jump) velocity = velocity - acceleration * drop;
  }
  return velocity;
}

// The 4 texel centres around a droplet at (pos_x, pos_y), erode4's: the corner cell ivec2(pos - 0.5)
// by truncation (as upstream, so within half a texel of x = 0 or y = 0 the weights leave [0, 1]),
// then +x, +y, +xy, with the bilinear weights (1-fx)(1-fy), fx(1-fy), (1-fx)fy, fx·fy.
template <class Real>
struct Corners {
  Texel cells[4];
  Real weights[4];
};

template <class Real>
Corners<Real> corners_around(Real pos_x, Real pos_y) {
  const Real corner_x = pos_x - Real(0.5), corner_y = pos_y - Real(0.5);
  const Texel corner{static_cast<int>(corner_x), static_cast<int>(corner_y)};  // truncation, as ivec2()
  const Real fx = corner_x - static_cast<Real>(corner.x), fy = corner_y - static_cast<Real>(corner.y);
  const Real gx = Real(1) - fx, gy = Real(1) - fy;
  return {{corner, {corner.x + 1, corner.y}, {corner.x, corner.y + 1}, {corner.x + 1, corner.y + 1}},
          {gx * gy, fx * gy, gx * fy, fx * fy}};
}

}  // namespace gt::reference
