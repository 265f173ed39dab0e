// Every key the `perpdot-scene/1` reader accepts, object by object (docs/scene-format.md).
// The reader refuses any other key with these lists, and a test checks that each key appears
// in docs/scene-format.md, so a key cannot be added without being documented.
#pragma once

#include <span>
#include <string_view>
#include <vector>

namespace perpdot::scene_keys {

using KeyList = std::span<const std::string_view>;

inline constexpr std::string_view root[] = {"format", "name",   "description", "gravity", "timestep",
                                            "steps",  "solver", "bodies",      "joints",  "actions"};
inline constexpr std::string_view solver[] = {"substeps", "velocity_iterations", "position_iterations", "box2d_skin"};
inline constexpr std::string_view body[] = {"name", "type", "position", "angle", "linear_velocity", "angular_velocity",
                                            "linear_damping", "angular_damping", "gravity_scale", "fixed_rotation",
                                            "bullet", "allow_sleep", "awake", "enabled", "shapes", "mass_data"};
inline constexpr std::string_view massData[] = {"mass", "center", "rotational_inertia"};

inline constexpr std::string_view filter[] = {"category", "mask", "group"};
inline constexpr std::string_view shape[] = {"type", "density", "friction", "restitution", "sensor", "filter", "enabled"};
inline constexpr std::string_view circle[] = {"radius", "center"};
inline constexpr std::string_view box[] = {"half_extents", "center", "angle"};
inline constexpr std::string_view polygon[] = {"vertices", "radius"};
inline constexpr std::string_view segment[] = {"v1", "v2"};
inline constexpr std::string_view chain[] = {"vertices", "loop", "solid", "prev_vertex", "next_vertex"};
inline constexpr std::string_view capsule[] = {"center1", "center2", "radius"};

inline constexpr std::string_view joint[] = {"type", "body_a", "body_b", "collide_connected", "break_force", "break_torque", "destroy_on_break"};
inline constexpr std::string_view jointAnchors[] = {"anchor", "local_anchor_a", "local_anchor_b"};
inline constexpr std::string_view revolute[] = {"enable_limit", "lower_angle", "upper_angle",
                                                "enable_motor", "motor_speed", "max_motor_torque"};
inline constexpr std::string_view distance[] = {"anchor_b", "length", "min_length", "max_length", "hertz", "damping_ratio"};
inline constexpr std::string_view prismatic[] = {"axis", "enable_limit", "lower", "upper",
                                                 "enable_motor", "motor_speed", "max_motor_force"};
inline constexpr std::string_view weld[] = {"hertz", "damping_ratio"};
inline constexpr std::string_view wheel[] = {"axis", "hertz", "damping_ratio", "enable_motor", "motor_speed", "max_motor_torque"};
inline constexpr std::string_view motor[] = {"linear_offset", "angular_offset", "max_force", "max_torque"};
inline constexpr std::string_view friction[] = {"max_force", "max_torque"};
inline constexpr std::string_view gear[] = {"joint_a", "joint_b", "ratio"};
inline constexpr std::string_view pulley[] = {"anchor_b", "ground_anchor_a", "ground_anchor_b", "length_a", "length_b", "ratio"};

inline constexpr std::string_view action[] = {"type", "body", "value", "first_step", "last_step"};
inline constexpr std::string_view actionPoint[] = {"point"};  // force and impulse only
inline constexpr std::string_view explosion[] = {"type", "point", "value", "radius", "blocked_by_static", "first_step", "last_step"};

// Every list above, for the documentation test.
inline std::vector<KeyList> all() {
    return {root,     solver, body,     filter,    shape, circle, box,   polygon, segment, chain, capsule,
            massData, joint, jointAnchors, revolute, distance, prismatic, weld, wheel, motor, friction, gear, pulley, action, actionPoint, explosion};
}

}  // namespace perpdot::scene_keys
