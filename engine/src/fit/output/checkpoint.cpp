// The checkpoint file (see checkpoint.h): "SVGMFIT3", the key, then counts and raw arrays; the
// schedule's state last ("SVGMFIT2" files, without it, are still read).
#include "fit/output/checkpoint.h"

#include <cstring>
#include <fstream>
#include <sstream>


#include "svgmotion/atomic_file.h"
#include "svgmotion/error.h"

namespace svgm {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'S', 'V', 'G', 'M', 'F', 'I', 'T', '3'};
constexpr char kMagicWithoutSchedule[8] = {'S', 'V', 'G', 'M', 'F', 'I', 'T', '2'};
// The finished fit's result after the state (animation_export.h): this tag, then its JSON.
constexpr char kResultMagic[8] = {'S', 'V', 'G', 'M', 'R', 'E', 'S', '1'};

template <class T>
void put(std::ostream& f, const std::vector<T>& v) {
  const uint64_t n = v.size();
  f.write(reinterpret_cast<const char*>(&n), sizeof n);
  f.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
}

template <class T>
bool get(std::ifstream& f, std::vector<T>& v) {
  uint64_t n = 0;
  if (!f.read(reinterpret_cast<char*>(&n), sizeof n) || n > (1ull << 32)) return false;
  v.resize(n);
  return static_cast<bool>(f.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T))));
}

}  // namespace

void save_checkpoint(const fs::path& file, const std::string& key, const FitState& s, const FitResult* result) {
  std::ostringstream f(std::ios::binary);
  f.write(kMagic, sizeof kMagic);
  put(f, std::vector<char>(key.begin(), key.end()));
  put(f, std::vector<int>{s.iteration, s.active});
  put(f, s.steps);
  for (const auto* v : {&s.params, &s.m_params, &s.v_params, &s.offsets, &s.m_offsets, &s.v_offsets,
                        &s.field, &s.m_field, &s.v_field})
    put(f, *v);
  put(f, std::vector<int>{s.converged ? 1 : 0, s.last_activation});
  put(f, std::vector<float>{s.newest_ref, s.lr_scale});
  put(f, s.plateau_ref);
  if (result) {
    const std::string head = std::string(kResultMagic, sizeof kResultMagic) + fit_result_json(*result);
    put(f, std::vector<char>(head.begin(), head.end()));
    put(f, result->points);
  }
  write_file_atomic(file, f.str());
}

namespace {

// Reads the state (after the magic and key); false when truncated.
bool read_state(std::ifstream& f, bool with_schedule, FitState& s) {
  std::vector<int> head;
  if (!get(f, head) || head.size() != 2 || !get(f, s.steps)) return false;
  for (auto* v : {&s.params, &s.m_params, &s.v_params, &s.offsets, &s.m_offsets, &s.v_offsets,
                  &s.field, &s.m_field, &s.v_field})
    if (!get(f, *v)) return false;
  s.iteration = head[0];
  s.active = head[1];
  if (!with_schedule) return true;
  std::vector<int> ints;
  std::vector<float> floats;
  if (!get(f, ints) || ints.size() != 2 || !get(f, floats) || floats.size() != 2 || !get(f, s.plateau_ref)) return false;
  s.schedule = true;
  s.converged = ints[0] != 0;
  s.last_activation = ints[1];
  s.newest_ref = floats[0];
  s.lr_scale = floats[1];
  return true;
}

}  // namespace

FitResult load_fit_result(const fs::path& file) {
  std::ifstream f(file, std::ios::binary);
  if (!f) throw Error(file.string() + ": cannot open: " + std::strerror(errno));
  char magic[8];
  std::vector<char> k;
  FitState s;
  if (!f.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0) {
    if (f && std::memcmp(magic, kMagicWithoutSchedule, sizeof magic) == 0)
      throw Error(file.string() + ": holds no finished fit to export (made by an older svgmotion); fit again");
    throw Error(file.string() + ": not an svgmotion checkpoint");
  }
  if (!get(f, k) || !read_state(f, true, s)) throw Error(file.string() + ": truncated checkpoint");
  std::vector<char> head;
  if (!get(f, head) || head.size() < sizeof kResultMagic || std::memcmp(head.data(), kResultMagic, sizeof kResultMagic) != 0)
    throw Error(file.string() + ": holds no finished fit to export (interrupted, or made by an older svgmotion); fit again");
  FitResult r = fit_result_from_json(std::string(head.begin() + sizeof kResultMagic, head.end()), file.string());
  if (!get(f, r.points) || r.points.size() != static_cast<size_t>(r.timing.keyframes) * r.n_cp * 2)
    throw Error(file.string() + ": truncated checkpoint");
  return r;
}

FitState load_checkpoint(const fs::path& file, const std::string& key) {
  std::ifstream f(file, std::ios::binary);
  if (!f) throw Error(file.string() + ": cannot open: " + std::strerror(errno));
  char magic[8];
  std::vector<char> k;
  FitState s;
  if (!f.read(magic, sizeof magic) ||
      (std::memcmp(magic, kMagic, sizeof magic) != 0 && std::memcmp(magic, kMagicWithoutSchedule, sizeof magic) != 0))
    throw Error(file.string() + ": not an svgmotion checkpoint");
  if (!get(f, k)) throw Error(file.string() + ": truncated checkpoint");
  if (std::string(k.begin(), k.end()) != key)
    throw Error(file.string() + ": made for another SVG, target or settings; remove it or drop --resume");
  if (!read_state(f, std::memcmp(magic, kMagic, sizeof magic) == 0, s)) throw Error(file.string() + ": truncated checkpoint");
  return s;
}

}  // namespace svgm
