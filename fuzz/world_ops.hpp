#pragma once
// The byte format of fuzz_world and its player: a byte string read as a sequence of operations on
// one to three Box2D 2.4.1 worlds (bodies, triangle fixtures by hand and through `add_triangles`,
// polygons, circles, edges, chains, moves, type changes, velocities, impulses, steps) with the
// plug-in installed,
// reconfigured and uninstalled among them, played to a hash of every world's final state.
//
// Format: `op_bytes` bytes per operation, at most `max_ops` of them; missing bytes read as zero,
// so every input decodes. Byte 0 picks the kind (`OpKind`, modulo their count), the others are its
// arguments, mostly indices into small tables (scales, time steps, speeds), so that a mutated byte
// gives another sensible operation. The player (world_ops.cpp) says what each one means and prints
// what it does.
//
// World 0 exists when a play starts (gravity -10 m/s²); the others come from `NewWorld`.
//
// The player never calls Box2D with what Box2D 2.4.1 asserts on (Debian builds it with b2Assert):
// such an operation is skipped, and printed as skipped. Bounds keep a play to milliseconds:
// `max_ops` operations, `max_steps` steps, `max_bodies` bodies and `max_fixtures` fixtures alive.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace dyop::fuzz {

inline constexpr std::size_t op_bytes = 8;
inline constexpr int max_ops = 200;
inline constexpr int max_steps = 60;
inline constexpr int max_bodies = 200;
inline constexpr int max_fixtures = 600;

enum class OpKind : std::uint8_t {
  NewWorld,
  EndWorld,  // destroying its bodies first, or a bare `delete`
  CreateBody,
  DestroyBody,
  AddTriangle,  // a b2PolygonShape of 3 vertices: any, sliver or needle
  AddMesh,      // `add_triangles`: a grid of cells, shared edges, a T-junction
  AddPolygon,   // 4 to 8 vertices
  AddCircle,
  DestroyFixture,
  Teleport,  // SetTransform
  SetType,   // static, kinematic, dynamic, bullet
  SetEnabled,
  SetVelocity,
  ApplyImpulse,
  Install,
  Uninstall,
  FixEdges,  // fix_internal_edges of a body or a world
  RefreshEdges,
  ForgetEdges,
  Step,
  WorldFlags,  // sleeping, warm starting, continuous physics, sub-stepping
  AddEdge,     // a b2EdgeShape, two-sided or one-sided (ghost vertices)
  AddChain,    // a b2ChainShape, open (ghost vertices) or a loop
  Count
};

struct WorldOp {
  OpKind kind = OpKind::NewWorld;
  std::array<std::uint8_t, op_bytes - 1> arg{};
};

std::vector<WorldOp> decode_world_ops(const std::uint8_t* data, std::size_t size);

// What the sequence's installs do in one play.
enum class Installs : std::uint8_t {
  AsWritten,  // each install's own backend and config
  Box2D,      // every install takes `Backend::Box2D`, with its config
  Never,      // installs and uninstalls do nothing: Box2D's own contact throughout
  Dyop,       // every install takes `Backend::Dyop`, with its config
  Sat,        // every install takes `Backend::Sat`, with its config
};

struct PlayResult {
  std::uint64_t hash = 0;  // every world's bodies, when it ended and at the end of the play
  bool finite = true;      // every body's position and angle finite after every step
  int played = 0;          // operations run (steps counted one each)
  int skipped = 0;         // operations skipped: no target, a bound, or Box2D would assert
  int steps = 0;
};

// Plays `ops` on fresh worlds, then steps every world once (1/60 s, 8/3 iterations, within
// `max_steps`), starting and ending with Box2D's own contact registered; `log`, when given, gets
// one line per operation.
PlayResult play_world_ops(const std::vector<WorldOp>& ops, Installs installs,
                          std::FILE* log = nullptr);

// The oracles of fuzz_world, each from the plays it needs.
struct WorldVerdict {
  bool finite = true;           // as written, no body position or angle goes NaN or infinite
  bool repeatable = true;       // as written twice in one process, the same hash
  bool box2d_is_own = true;     // `Box2D` ends bit-identical to `Never`
  bool dyop_is_sat = true;      // `Dyop` ends bit-identical to `Sat`
  PlayResult as_written;        // the first play as written
  const char* failure() const;  // the first property broken, or nullptr
};

WorldVerdict judge_world_ops(const std::vector<WorldOp>& ops);

}  // namespace dyop::fuzz
