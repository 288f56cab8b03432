#include "io/base/text.h"

#include "geom/errors.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace clumpkit {

namespace fs = std::filesystem;

std::string read_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) throw IoError(path + ": file not found");
  if (fs::is_directory(st)) throw IoError(path + ": is a directory, not a " + what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot open " + what + ": " + std::strerror(errno));
  // One allocation and one read of a regular file's size (a scan's STL is 60 MB, and a string
  // stream's growing buffer copied it three times), then whatever a growing file added since.
  std::string data;
  std::error_code size_ec;
  const std::uintmax_t size = fs::is_regular_file(st) ? fs::file_size(path, size_ec) : 0;
  if (!size_ec && size > 0) {
    data.resize(static_cast<std::size_t>(size));
    in.read(data.data(), static_cast<std::streamsize>(size));
    data.resize(static_cast<std::size_t>(in.gcount()));
    if (in.bad()) throw IoError(path + ": read failed");
    if (in.eof()) return data;  // shrank while read: what is there
  }
  std::ostringstream rest;
  rest << in.rdbuf();
  if (in.bad()) throw IoError(path + ": read failed");
  data += rest.str();
  return data;
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  return out;
}

namespace {

template <class T>
std::optional<T> whole(std::string_view s) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
  T v{};
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

}  // namespace

std::optional<double> to_number(std::string_view token) {
  return whole<double>(token);
}

std::optional<long long> to_integer(std::string_view token) {
  return whole<long long>(token);
}

void LineReader::fail(const std::string& why) const {
  throw InvalidInput(path + ":" + std::to_string(line) + ": " + why);
}

double LineReader::number(const std::string& cell, const char* field) const {
  const std::optional<double> v = to_number(cell);
  if (!v || !std::isfinite(*v))
    fail("field " + std::string(field) + ": not a finite number: '" + cell + "'");
  return *v;
}

std::string csv_escape(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string id_name(std::size_t i) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%05zu", i);
  return buf;
}

}  // namespace clumpkit
