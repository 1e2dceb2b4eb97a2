#pragma once
/// \file
/// The worlds the scenes are built of: the Box2D worlds of triangle fixtures of `box2d_worlds/`
/// (shared with the bridge's tests and the world fuzzer), named in the scenes' namespace.

#include "worlds/world.hpp"

namespace dyop::scenes {

using worlds::add_body;
using worlds::add_l_shape;
using worlds::add_split_box;
using worlds::add_star;
using worlds::add_triangle;
using worlds::add_triangle_bin;
using worlds::add_triangle_block;
using worlds::add_triangle_ground;
using worlds::add_u_shape;
using worlds::is_triangle;
using worlds::Material;
using worlds::position_iterations;
using worlds::state_hash;
using worlds::steps_per_second;
using worlds::time_step;
using worlds::velocity_iterations;
using worlds::World;

}  // namespace dyop::scenes
