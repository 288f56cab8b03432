#include "io/formats/checkpoint.h"

#include "geom/errors.h"
#include "geom/hash.h"
#include "io/base/atomic_file.h"
#include "io/base/little_endian.h"
#include "io/base/text.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>

namespace clumpkit {

using namespace dem;

namespace {

constexpr char kMagic[12] = {'C', 'L', 'U', 'M', 'P', 'K', 'I', 'T', 'C', 'K', 'P', 'T'};

// Little-endian encoder.
class Writer {
 public:
  std::string bytes;

  void u8(std::uint8_t v) { bytes.push_back(static_cast<char>(v)); }
  void u32(std::uint32_t v) { append_le(bytes, v); }
  void u64(std::uint64_t v) { append_le(bytes, v); }
  void i32(int v) { u32(static_cast<std::uint32_t>(v)); }
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  void f64(double v) { append_le(bytes, v); }
  void vec(const Vec3& v) {
    for (int k = 0; k < 3; ++k) f64(v[k]);
  }
  void quat(const Eigen::Quaterniond& q) { f64(q.w()), f64(q.x()), f64(q.y()), f64(q.z()); }
  void str(const std::string& s) {
    u64(s.size());
    bytes += s;
  }
  void state(const ContactState& s) {
    vec(s.normal), vec(s.point), f64(s.overlap), f64(s.normal_force), vec(s.shear), f64(s.excused);
  }
};

// Little-endian decoder over the whole file; every read checks the remaining length.
class Reader {
 public:
  Reader(const std::string& bytes, std::size_t end, const std::string& path)
      : bytes_(bytes), end_(end), path_(path) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidInput("checkpoint " + path_ + ": " + what);
  }
  std::size_t position() const { return pos_; }

  std::uint8_t u8() {
    need(1);
    return static_cast<std::uint8_t>(bytes_[pos_++]);
  }
  std::uint32_t u32() { return take<std::uint32_t>(); }
  std::uint64_t u64() { return take<std::uint64_t>(); }
  int i32() { return static_cast<int>(u32()); }
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
  double f64() { return take<double>(); }
  Vec3 vec() {
    Vec3 v;
    for (int k = 0; k < 3; ++k) v[k] = f64();
    return v;
  }
  Eigen::Quaterniond quat() {
    const double w = f64(), x = f64(), y = f64(), z = f64();
    return Eigen::Quaterniond(w, x, y, z);
  }
  /// A count of items of at least `item_bytes` each, checked against the bytes left.
  std::size_t count(std::size_t item_bytes, const char* what) {
    const std::uint64_t n = u64();
    if (n > (end_ - pos_) / item_bytes)
      fail(std::string("truncated or corrupt file (") + what + " count " + std::to_string(n) +
           " exceeds the remaining bytes)");
    return static_cast<std::size_t>(n);
  }
  std::string str(const char* what) {
    const std::size_t n = count(1, what);
    std::string s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  ContactState state() {
    ContactState s;
    s.normal = vec();
    s.point = vec();
    s.overlap = f64();
    s.normal_force = f64();
    s.shear = vec();
    s.excused = f64();
    return s;
  }

 private:
  void need(std::size_t n) const {
    if (end_ - pos_ < n)
      fail("truncated file (needed " + std::to_string(n) + " more bytes at offset " +
           std::to_string(pos_) + ")");
  }
  template <class T>
  T take() {
    need(sizeof(T));
    const T v = load_le<T>(bytes_.data() + pos_);
    pos_ += sizeof(T);
    return v;
  }

  const std::string& bytes_;
  std::size_t end_;
  std::size_t pos_ = 0;
  std::string path_;
};

constexpr std::size_t kStateBytes = 12 * 8;
constexpr std::size_t kHeaderBytes = sizeof kMagic + 4;
constexpr std::size_t kChecksumBytes = 8;

}  // namespace

namespace {

// The world through its public interface: options, bodies, walls, contact lists and
// World::list_state (clock and Verlet lists).
struct WorldCodec {
  static void write(Writer& w, const World& world) {
    const WorldOptions& o = world.options();
    const World::ListState lists = world.list_state();
    w.vec(o.gravity);
    w.f64(o.timestep);
    w.f64(o.skin);
    w.f64(o.near_skin_fraction);
    w.i32(o.sort_every);
    w.f64(o.contact.kn), w.f64(o.contact.ks), w.f64(o.contact.friction);
    w.f64(o.contact.damping_ratio), w.f64(o.contact.local_damping);
    w.u8(o.contact.scaling == StiffnessScaling::none ? 0 : 1), w.f64(o.contact.d_ref);
    w.f64(o.cohesive.kn), w.f64(o.cohesive.kt), w.f64(o.cohesive.sigma_n);
    w.f64(o.cohesive.sigma_t), w.f64(o.cohesive.g_n), w.f64(o.cohesive.g_t);
    w.f64(o.cohesive.friction);
    w.f64(o.vertex_stiffness);
    w.u8(o.broken_bonds_act ? 1 : 0);
    w.i64(lists.steps);
    w.f64(lists.time);
    w.i64(lists.builds);
    w.u8(lists.stale ? 1 : 0);

    w.u64(world.bodies().size());
    for (const Body& b : world.bodies()) {
      w.u64(b.spheres.size());
      for (const Sphere& s : b.spheres) w.vec(s.center), w.f64(s.radius);
      w.f64(b.mass);
      w.vec(b.moments);
      w.vec(b.position), w.vec(b.velocity), w.quat(b.orientation), w.vec(b.angular_velocity);
      w.vec(b.force), w.vec(b.torque);
      w.u8(b.rotation_locked ? 1 : 0);
      w.f64(b.volume);
      w.u8(static_cast<std::uint8_t>(b.kind));
      w.i32(b.template_id);
      w.f64(b.scale);
      w.f64(b.diameter);
      w.i32(b.zone);
      w.u64(b.vertices.size());
      for (const Vec3& v : b.vertices) w.vec(v);
    }
    w.u64(world.walls().size());
    for (const Wall& wall : world.walls()) {
      w.u8(static_cast<std::uint8_t>(wall.kind));  // 0 plane, 1 cylinder, 2 probe
      w.vec(wall.point), w.vec(wall.normal), w.f64(wall.radius), w.vec(wall.velocity);
      w.f64(wall.radial_velocity), w.f64(wall.friction);
      if (wall.kind == Wall::Kind::probe) {  // its profile after the common fields
        w.u64(wall.profile.size());
        for (const Eigen::Vector2d& x : wall.profile) w.f64(x.x()), w.f64(x.y());
        w.i32(wall.sleeve_from);
      }
    }
    w.u64(world.bonds().size());
    for (const Bond& bond : world.bonds()) {
      w.i32(bond.a), w.i32(bond.b), w.vec(bond.normal_in_a), w.f64(bond.factor);
      w.u64(bond.points.size());
      for (const BondPoint& p : bond.points)
        w.vec(p.in_a), w.vec(p.in_b), w.f64(p.area), w.f64(p.state.damage), w.vec(p.state.slip),
            w.f64(p.state.failure_mix);
    }
    w.u64(world.contacts().size());
    for (const PairContact& c : world.contacts()) w.i32(c.i), w.i32(c.j), w.state(c.state);
    w.u64(world.wall_contacts().size());
    for (const WallContact& c : world.wall_contacts())
      w.i32(c.sphere), w.i32(c.wall), w.state(c.state);
    w.u64(world.vertex_contacts().size());
    for (const VertexContact& c : world.vertex_contacts())
      w.i32(c.body), w.i32(c.vertex), w.i32(c.wall), w.state(c.state);
    w.u64(lists.build_positions.size());
    for (const Vec3& x : lists.build_positions) w.vec(x);
    w.u64(lists.skin_pairs.size());
    for (const auto& [i, j] : lists.skin_pairs) w.i32(i), w.i32(j);
    // The near list itself is filtered again on loading, from these.
    w.u64(lists.filter_positions.size());
    for (const Vec3& x : lists.filter_positions) w.vec(x);
    w.f64(lists.near_limit);
    w.i64(lists.filters);
  }

  // Reads the current format (kCheckpointVersion) only.
  static World read(Reader& r) {
    const WorldOptions o = read_options(r);
    const std::int64_t steps = r.i64();
    const double time = r.f64();
    const std::int64_t builds = r.i64();
    const std::uint8_t dirty = r.u8();
    if (dirty > 1) r.fail("corrupt neighbour-list flag " + std::to_string(dirty));

    World world = [&] {
      try {
        return World(o);
      } catch (const InvalidInput& e) {
        r.fail(e.what());
      }
    }();

    read_bodies(r, world);
    read_walls(r, world);
    read_bonds(r, world);
    restore_contacts_and_lists(r, world, steps, time, builds, dirty);
    return world;
  }

  // The world's options, each checked where a value could be out of range.
  static WorldOptions read_options(Reader& r) {
    WorldOptions o;
    o.gravity = r.vec();
    o.timestep = r.f64();
    o.skin = r.f64();
    o.near_skin_fraction = r.f64();
    o.sort_every = r.i32();
    if (o.sort_every < 0) r.fail("negative sort interval " + std::to_string(o.sort_every));
    o.contact.kn = r.f64(), o.contact.ks = r.f64(), o.contact.friction = r.f64();
    o.contact.damping_ratio = r.f64(), o.contact.local_damping = r.f64();
    const std::uint8_t scaling = r.u8();
    if (scaling > 1) r.fail("unknown stiffness scaling " + std::to_string(scaling));
    o.contact.scaling = scaling == 0 ? StiffnessScaling::none : StiffnessScaling::linear;
    o.contact.d_ref = r.f64();
    o.cohesive.kn = r.f64(), o.cohesive.kt = r.f64(), o.cohesive.sigma_n = r.f64();
    o.cohesive.sigma_t = r.f64(), o.cohesive.g_n = r.f64(), o.cohesive.g_t = r.f64();
    o.cohesive.friction = r.f64();
    if (!(o.cohesive.friction >= 0.0) || !std::isfinite(o.cohesive.friction))
      r.fail("cohesive friction " + std::to_string(o.cohesive.friction) + " is not valid");
    o.vertex_stiffness = r.f64();
    const std::uint8_t broken_act = r.u8();
    if (broken_act > 1) r.fail("corrupt broken-bond flag " + std::to_string(broken_act));
    o.broken_bonds_act = broken_act == 1;
    return o;
  }

  // The bodies, added to the world in order (orientations kept bit for bit).
  static void read_bodies(Reader& r, World& world) {
    const std::size_t bodies = r.count(8, "body");
    for (std::size_t k = 0; k < bodies; ++k) {
      Body b;
      const std::size_t spheres = r.count(32, "sphere");
      for (std::size_t s = 0; s < spheres; ++s) {
        const Vec3 c = r.vec();
        b.spheres.push_back(Sphere{c, r.f64()});
      }
      b.mass = r.f64();
      b.moments = r.vec();
      b.position = r.vec(), b.velocity = r.vec(), b.orientation = r.quat();
      b.angular_velocity = r.vec();
      b.force = r.vec(), b.torque = r.vec();
      const std::uint8_t locked = r.u8();
      if (locked > 1) r.fail("corrupt rotation lock of body " + std::to_string(k));
      b.rotation_locked = locked == 1;
      b.volume = r.f64();
      const std::uint8_t kind = r.u8();
      if (kind > 1)
        r.fail("unknown kind " + std::to_string(kind) + " of body " + std::to_string(k));
      b.kind = static_cast<BodyKind>(kind);
      b.template_id = r.i32();
      b.scale = r.f64();
      b.diameter = r.f64();
      b.zone = r.i32();
      b.vertices.resize(r.count(24, "body corner"));
      for (Vec3& v : b.vertices) v = r.vec();
      const Eigen::Quaterniond q = b.orientation;
      try {
        world.add_body(std::move(b));
      } catch (const InvalidInput& e) {
        r.fail("body " + std::to_string(k) + ": " + e.what());
      }
      world.bodies().back().orientation = q;  // exact bits, not re-normalised
    }
  }

  // The walls, a probe's profile validated.
  static void read_walls(Reader& r, World& world) {
    const std::size_t walls = r.count(1 + 12 * 8, "wall");
    for (std::size_t k = 0; k < walls; ++k) {
      Wall wall;
      const std::uint8_t kind = r.u8();
      if (kind > 2)
        r.fail("unknown kind " + std::to_string(kind) + " of wall " + std::to_string(k));
      wall.kind = static_cast<Wall::Kind>(kind);
      wall.point = r.vec(), wall.normal = r.vec(), wall.radius = r.f64(), wall.velocity = r.vec();
      wall.radial_velocity = r.f64(), wall.friction = r.f64();
      if (wall.kind == Wall::Kind::probe) {
        const std::size_t points = r.count(16, "probe profile point");
        if (points < 1) r.fail("probe wall " + std::to_string(k) + " has no profile");
        wall.profile.resize(points);
        for (Eigen::Vector2d& x : wall.profile) x.x() = r.f64(), x.y() = r.f64();
        wall.sleeve_from = r.i32();
        try {
          validate_probe_profile(wall);
        } catch (const InvalidInput& e) {
          r.fail("wall " + std::to_string(k) + ": " + e.what());
        }
      }
      world.add_wall(wall);
    }
  }

  // The bonds, each point's damage and failure mix checked.
  static void read_bonds(Reader& r, World& world) {
    const std::size_t bonds = r.count(8 + 24 + 8 + 8, "bond");
    for (std::size_t k = 0; k < bonds; ++k) {
      Bond bond;
      bond.a = r.i32(), bond.b = r.i32();
      bond.normal_in_a = r.vec();
      bond.factor = r.f64();
      bond.points.resize(r.count(12 * 8, "bond point"));
      for (BondPoint& p : bond.points) {
        p.in_a = r.vec(), p.in_b = r.vec(), p.area = r.f64(), p.state.damage = r.f64();
        p.state.slip = r.vec();
        p.state.failure_mix = r.f64();
        if (!(p.state.damage >= 0.0 && p.state.damage <= 1.0))
          r.fail("bond " + std::to_string(k) + " has a damage outside [0, 1]");
        if (!(p.state.failure_mix >= 0.0 && p.state.failure_mix <= 1.0))
          r.fail("bond " + std::to_string(k) + " has a failure mix outside [0, 1]");
      }
      try {
        world.add_bond(std::move(bond));
      } catch (const InvalidInput& e) {
        r.fail("bond " + std::to_string(k) + ": " + e.what());
      }
    }
  }

  // The contact lists and neighbour lists (their sphere and wall indices checked), restored
  // together with the clock read before the bodies.
  static void restore_contacts_and_lists(Reader& r, World& world, std::int64_t steps, double time,
                                         std::int64_t builds, std::uint8_t dirty) {
    const int n_spheres = world.sphere_count();
    const int n_walls = static_cast<int>(world.walls().size());
    auto check_sphere = [&](int s, const char* what) {
      if (s < 0 || s >= n_spheres)
        r.fail(std::string(what) + " refers to sphere " + std::to_string(s) + " of " +
               std::to_string(n_spheres));
    };

    const std::size_t contacts = r.count(8 + kStateBytes, "contact");
    std::vector<PairContact> pair_contacts(contacts);
    for (PairContact& c : pair_contacts) {
      c.i = r.i32(), c.j = r.i32();
      check_sphere(c.i, "contact"), check_sphere(c.j, "contact");
      c.state = r.state();
    }
    const std::size_t wall_contacts = r.count(8 + kStateBytes, "wall contact");
    std::vector<WallContact> wall_list(wall_contacts);
    for (WallContact& c : wall_list) {
      c.sphere = r.i32(), c.wall = r.i32();
      check_sphere(c.sphere, "wall contact");
      if (c.wall < 0 || c.wall >= n_walls)
        r.fail("wall contact refers to wall " + std::to_string(c.wall) + " of " +
               std::to_string(n_walls));
      c.state = r.state();
    }

    std::vector<VertexContact> corner_list;
    {
      corner_list.resize(r.count(12 + kStateBytes, "corner contact"));
      for (VertexContact& c : corner_list) {
        c.body = r.i32(), c.vertex = r.i32(), c.wall = r.i32();
        c.state = r.state();
      }
    }

    // Reference positions of a neighbour list: none (never built) or one per sphere.
    auto read_positions = [&](std::vector<Vec3>& out, const std::string& list) {
      const std::size_t count = r.count(24, (list + " position").c_str());
      if (count != 0 && count != static_cast<std::size_t>(n_spheres))
        r.fail(list + " holds " + std::to_string(count) + " positions for " +
               std::to_string(n_spheres) + " spheres");
      out.resize(count);
      for (Vec3& x : out) x = r.vec();
    };
    World::ListState lists;
    read_positions(lists.build_positions, "neighbour list");
    const std::size_t candidates = r.count(8, "neighbour pair");
    lists.skin_pairs.resize(candidates);
    for (auto& [i, j] : lists.skin_pairs) {
      i = r.i32(), j = r.i32();
      check_sphere(i, "neighbour pair"), check_sphere(j, "neighbour pair");
    }
    read_positions(lists.filter_positions, "near list");
    lists.near_limit = r.f64();
    if (!(lists.near_limit >= 0.0)) r.fail("corrupt near-list limit");
    lists.filters = r.i64();
    lists.steps = steps;
    lists.time = time;
    lists.builds = builds;
    lists.stale = dirty == 1;
    try {
      world.restore(std::move(lists), std::move(pair_contacts), std::move(wall_list));
      world.restore_vertex_contacts(std::move(corner_list));
    } catch (const InvalidInput& e) {
      r.fail(e.what());
    }
  }
};

}  // namespace

void save_checkpoint(const std::string& path, const World& world, const CheckpointInfo& info) {
  Writer w;
  w.bytes.append(kMagic, sizeof kMagic);
  w.u32(kCheckpointVersion);
  w.str(info.stage);
  w.u64(info.state.size());
  for (const auto& [key, value] : info.state) w.str(key), w.str(value);
  WorldCodec::write(w, world);
  w.u64(fnv1a(w.bytes.data(), w.bytes.size()));

  write_file_atomically(path, [&](std::ostream& out) {
    out.write(w.bytes.data(), static_cast<std::streamsize>(w.bytes.size()));
  });
}

World load_checkpoint(const std::string& path, CheckpointInfo* info) {
  const std::string bytes = read_file(path, "checkpoint");

  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw InvalidInput("checkpoint " + path + ": not a clumpkit checkpoint (bad magic)");
  if (bytes.size() < kHeaderBytes + kChecksumBytes)
    throw InvalidInput("checkpoint " + path + ": truncated file (" + std::to_string(bytes.size()) +
                       " bytes)");
  const std::size_t end = bytes.size() - kChecksumBytes;
  Reader header(bytes, end, path);
  for (std::size_t k = 0; k < sizeof kMagic; ++k) header.u8();
  const std::uint32_t version = header.u32();
  if (version != kCheckpointVersion)
    header.fail("unsupported version " + std::to_string(version) + " (expected " +
                std::to_string(kCheckpointVersion) + ")");
  std::uint64_t stored = 0;
  for (std::size_t k = 0; k < kChecksumBytes; ++k)
    stored |= std::uint64_t(static_cast<unsigned char>(bytes[end + k])) << (8 * k);
  if (stored != fnv1a(bytes.data(), end))
    header.fail("checksum mismatch (truncated or corrupt file)");

  CheckpointInfo read_info;
  read_info.stage = header.str("stage");
  const std::size_t entries = header.count(16, "stage state");  // two lengths each at least
  for (std::size_t k = 0; k < entries; ++k) {
    std::string key = header.str("stage state key");
    read_info.state[std::move(key)] = header.str("stage state value");
  }
  if (read_info.state.size() != entries) header.fail("repeated stage state key");
  World world = WorldCodec::read(header);
  if (header.position() != end)
    header.fail(std::to_string(end - header.position()) + " unexpected bytes before the checksum");
  if (info) *info = std::move(read_info);
  return world;
}

}  // namespace clumpkit
