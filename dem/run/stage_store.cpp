#include "dem/run/stage_store.h"

#include "geom/errors.h"
#include "geom/format.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace clumpkit::dem {

namespace {

const std::string& value_at(const StageRecord& record, const std::string& key,
                            const std::string& where) {
  const auto it = record.find(key);
  if (it == record.end()) throw InvalidInput(where + ": stage record misses " + key);
  return it->second;
}

template <class T>
T parse(const StageRecord& record, const std::string& key, const std::string& where) {
  const std::string& text = value_at(record, key, where);
  T v{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size())
    throw InvalidInput(where + ": stage record " + key + ": '" + text + "' is not a number");
  return v;
}

}  // namespace

void put_number(StageRecord& record, const std::string& key, double value) {
  record[key] = format_number(value);
}

double record_number(const StageRecord& record, const std::string& key, const std::string& where) {
  // format_number writes "nan", "inf" and "-inf" for the non-finite values, which from_chars
  // reads back.
  return parse<double>(record, key, where);
}

long long record_integer(const StageRecord& record, const std::string& key,
                         const std::string& where) {
  return parse<long long>(record, key, where);
}

std::vector<double> record_list(const StageRecord& record, const std::string& key,
                                const std::string& where) {
  const std::string& text = value_at(record, key, where);
  std::vector<double> out;
  const char* p = text.data();
  const char* end = p + text.size();
  while (true) {
    double v = 0;
    const auto [next, ec] = std::from_chars(p, end, v);
    if (ec != std::errc() || (next != end && *next != ','))
      throw InvalidInput(where + ": stage record " + key + ": '" + text + "' is not numbers");
    out.push_back(v);
    if (next == end) return out;
    p = next + 1;
  }
}

namespace {

std::string row_key(std::size_t k) {
  char key[32];
  std::snprintf(key, sizeof key, "curve.%06zu", k);
  return key;
}

}  // namespace

void put_curve(StageRecord& record, const std::vector<std::vector<double>>& rows) {
  record["curve.rows"] = std::to_string(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    std::string text;
    for (std::size_t f = 0; f < rows[k].size(); ++f)
      text += (f ? "," : "") + format_number(rows[k][f]);
    record[row_key(k)] = text;
  }
}

std::vector<std::vector<double>> record_curve(const StageRecord& record, std::size_t fields,
                                              const std::string& where) {
  const long long rows = record_integer(record, "curve.rows", where);
  if (rows < 0) throw InvalidInput(where + ": stage record curve.rows is negative");
  std::vector<std::vector<double>> out;
  for (long long k = 0; k < rows; ++k) {
    const std::string key = row_key(static_cast<std::size_t>(k));
    out.push_back(record_list(record, key, where));
    if (out.back().size() != fields)
      throw InvalidInput(where + ": stage record " + key + ": expected " + std::to_string(fields) +
                         " numbers");
  }
  return out;
}

StageCheckpoints::StageCheckpoints(StageStore& store, const StageControl& control,
                                   std::string stage)
    : store_(store),
      control_(control),
      stage_(std::move(stage)),
      last_(std::chrono::steady_clock::now()) {}

void StageCheckpoints::save(const World& world, const StageRecord& state) {
  if (!store_.keeps_checkpoints()) return;
  store_.checkpoint(stage_, world, CheckpointInfo{stage_, state});
  last_ = std::chrono::steady_clock::now();
}

bool StageCheckpoints::check(const World& world, const std::function<StageRecord()>& state,
                             std::string_view what, double fraction) {
  if (store_.keeps_checkpoints() && control_.checkpoint_every_seconds > 0 &&
      std::chrono::duration<double>(std::chrono::steady_clock::now() - last_).count() >=
          control_.checkpoint_every_seconds)
    save(world, state());
  if (!interrupted(control_.interrupter, what, std::clamp(fraction, 0.0, 1.0))) return false;
  if (store_.keeps_checkpoints()) save(world, state());
  return true;
}

StageStore& store_of(const StageControl& control) {
  static StageStore keeps_nothing;
  return control.store ? *control.store : keeps_nothing;
}

}  // namespace clumpkit::dem
