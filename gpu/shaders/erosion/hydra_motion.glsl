// Droplet motion that seed 000's particle erosion (particle_droplets.comp) and its flow map
// (flow_map_droplets.comp) share (digest 000 Appendix A).
// Positions in texels, heights in the caller's units. All arithmetic `precise`, in the reference's
// order.
// Inputs:  a droplet's velocity component, height and neighbours' heights; its position.
// Outputs: the accelerated velocity component; the 4 texels around the droplet and their bilinear
//          weights.
// Twin:    reference/erosion/hydra_motion.hpp.
#ifndef HYDRA_MOTION_GLSL
#define HYDRA_MOTION_GLSL

// std::max(a, b) = a < b ? b : a and std::min(a, b) = b < a ? b : a, signed zeros and NaN as the
// float reference evaluates them (GLSL's max/min leave those cases open).
float ref_max(float a, float b) { return a < b ? b : a; }
float ref_min(float a, float b) { return b < a ? b : a; }

// Algorithm 4 along one axis as upstream nests it: `speed` is the velocity component, `plus_height`
// / `minus_height` the neighbours at +1 / -1 along that axis, `height` the texel's. The sign of the
// velocity picks the neighbour; a drop beyond `max_jump` leaves the velocity unchanged.
float accelerated_axis(float speed, float height, float plus_height, float minus_height, float acceleration,
                       float max_jump) {
  precise float result = speed;
  if (speed > 0.0) {
    precise float drop = height - plus_height;
    if (drop <= max_jump) result = speed + acceleration * drop;
  } else {
    precise float drop = height - minus_height;
    if (drop <= max_jump) result = speed - acceleration * drop;
  }
  return result;
}

// erode4's corners in the order they are visited: (0,0), (1,0), (0,1), (1,1).
const ivec2 corner_offsets[4] = ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 1));

// erode4's sample point pos - (0.5, 0.5); its corner cell (0,0) is ivec2(point), truncated toward
// zero as upstream.
vec2 corner_point(vec2 position) {
  precise vec2 point = vec2(position.x - 0.5, position.y - 0.5);
  return point;
}

// Bilinear weights of the corners (0,0), (1,0), (0,1), (1,1) for the sample point `point` whose
// corner cell is `corner`: (1-f.x)(1-f.y), f.x(1-f.y), (1-f.x)f.y, f.x·f.y with f = point - corner.
vec4 bilinear_weights(vec2 point, ivec2 corner) {
  precise vec2 fraction = vec2(point.x - float(corner.x), point.y - float(corner.y));
  precise float rest_x = 1.0 - fraction.x;
  precise float rest_y = 1.0 - fraction.y;
  precise vec4 weights = vec4(rest_x * rest_y, fraction.x * rest_y, rest_x * fraction.y, fraction.x * fraction.y);
  return weights;
}

#endif
