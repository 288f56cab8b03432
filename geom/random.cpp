#include "geom/random.h"

#include <cmath>

namespace clumpkit {

namespace {
std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
std::uint64_t rotl(std::uint64_t x, int k) {
  return (x << k) | (x >> (64 - k));
}
}  // namespace

Rng::Rng(std::uint64_t seed) {
  for (auto& s : s_) s = splitmix64(seed);
}

Rng Rng::stream(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t x = seed;
  const std::uint64_t a = splitmix64(x);
  std::uint64_t y = index ^ 0xd1b54a32d192ed03ULL;
  return Rng(a ^ splitmix64(y));
}

std::uint64_t Rng::next() {
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double Rng::uniform() {
  return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

double Rng::uniform(double lo, double hi) {
  return lo + (hi - lo) * uniform();
}

Vec3 Rng::uniform(const Vec3& lo, const Vec3& hi) {
  const double z = uniform(lo.z(), hi.z());
  const double y = uniform(lo.y(), hi.y());
  const double x = uniform(lo.x(), hi.x());
  return Vec3(x, y, z);
}

std::uint64_t Rng::below(std::uint64_t n) {
  return n == 0 ? 0 : next() % n;
}

double Rng::normal() {
  double u1 = uniform();
  while (u1 <= 0.0) u1 = uniform();
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

Eigen::Quaterniond Rng::normal_quaternion() {
  const double z = normal();
  const double y = normal();
  const double x = normal();
  const double w = normal();
  return Eigen::Quaterniond(w, x, y, z);
}

Vec3 Rng::unit_vector() {
  const double z = uniform(-1.0, 1.0);
  const double phi = uniform(0.0, 2.0 * M_PI);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

}  // namespace clumpkit
