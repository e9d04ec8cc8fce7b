// The WordNet reader (see wordnet.h): memory-mapped index and data files, binary search of the
// index, synsets parsed from the data line at the index's byte offset, morphy's exceptions and
// detachment rules.
#include "motion/wordnet.h"
#include "motion/wordnet_pages.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "svgmotion/log.h"

namespace svgm::wordnet {

// One read-only mapping of a whole file; pages are read as lookups touch them.
struct Database::File {
  const char* data = nullptr;
  size_t size = 0;
  ~File() {
    if (data) munmap(const_cast<char*>(data), size);
  }
  std::string_view view() const { return {data, size}; }
};

struct Database::Exceptions {
  std::unordered_map<std::string, std::vector<std::string>> by_pos[4];
};

namespace {

constexpr const char* kPosName[4] = {"noun", "verb", "adj", "adv"};

std::unique_ptr<Database::File> map_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return nullptr;
  struct stat st{};
  void* p = MAP_FAILED;
  if (fstat(fd, &st) == 0 && st.st_size > 0) p = mmap(nullptr, static_cast<size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
  ::close(fd);
  if (p == MAP_FAILED) return nullptr;
  auto f = std::make_unique<Database::File>();
  f->data = static_cast<const char*>(p);
  f->size = static_cast<size_t>(st.st_size);
  return f;
}

std::string_view first_field(std::string_view line) { return line.substr(0, line.find(' ')); }

// Space-separated fields of a line (up to the gloss's '|').
std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> out;
  size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && line[at] == ' ') ++at;
    if (at >= line.size() || line[at] == '|') break;
    const size_t end = std::min(line.find(' ', at), line.size());
    out.push_back(line.substr(at, end - at));
    at = end;
  }
  return out;
}

unsigned long number(std::string_view s, int base) { return std::strtoul(std::string(s).c_str(), nullptr, base); }

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

}  // namespace

Pos pos_of_char(char c) {
  switch (c) {
    case 'v': return Pos::Verb;
    case 'a': case 's': return Pos::Adj;
    case 'r': return Pos::Adv;
    default: return Pos::Noun;
  }
}

Database::~Database() = default;

std::unique_ptr<Database> Database::open(const std::string& dir) {
  std::unique_ptr<Database> db(new Database());
  db->dir_ = dir;
  db->exc_ = std::make_unique<Exceptions>();
  for (int p = 0; p < 4; ++p) {
    db->index_[p] = map_file(dir + "/index." + kPosName[p]);
    db->data_[p] = map_file(dir + "/data." + kPosName[p]);
    if (!db->index_[p] || !db->data_[p]) return nullptr;
    // "geese goose", "ran run": inflected form, then its base forms.
    std::ifstream exc(dir + "/" + kPosName[p] + ".exc");
    for (std::string line; std::getline(exc, line);) {
      std::istringstream in(line);
      std::string form, base;
      in >> form;
      while (in >> base) db->exc_->by_pos[p][form].push_back(base);
    }
  }
  return db;
}

namespace {

// The shared database's folder (see the file comment); empty when none is configured.
std::string shared_dir() {
  const char* env = std::getenv("SVGM_WORDNET_DIR");
#ifdef SVGM_WORDNET_DEFAULT_DIR
  return env && *env ? env : SVGM_WORDNET_DEFAULT_DIR;
#else
  return env && *env ? env : "";
#endif
}

}  // namespace

void release_shared_pages() {
  // Every mapping of the folder's files (wordnet_pages.h).
  const std::string dir = shared_dir();
  if (dir.empty()) return;
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    // "start-end perms offset dev inode path"
    const size_t slash = line.find('/');
    if (slash == std::string::npos || line.compare(slash, dir.size() + 1, dir + "/") != 0) continue;
    const uintptr_t from = std::strtoull(line.c_str(), nullptr, 16);
    const uintptr_t to = std::strtoull(line.c_str() + line.find('-') + 1, nullptr, 16);
    if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
  }
}

const Database* Database::shared() {
  static const std::unique_ptr<Database> db = [] {
    const std::string dir = shared_dir();
    std::unique_ptr<Database> d = dir.empty() ? nullptr : open(dir);
    if (!d)
      log::info("motion words: no WordNet database%s%s (install wordnet-base or set SVGM_WORDNET_DIR); "
                "words outside the motion vocabulary are not read",
                dir.empty() ? "" : " in ", dir.c_str());
    return d;
  }();
  return db.get();
}

std::string_view Database::index_line(std::string_view lemma, Pos pos) const {
  const std::string_view f = index_[static_cast<int>(pos)]->view();
  // Binary search over byte positions: each probe backs up to its line's start. The licence
  // lines at the top start with a space, so their first field is empty and sorts first.
  size_t lo = 0, hi = f.size();
  while (lo < hi) {
    const size_t mid = lo + (hi - lo) / 2;
    size_t start = f.rfind('\n', mid == 0 ? 0 : mid - 1);
    start = start == std::string_view::npos || mid == 0 ? 0 : start + 1;
    const size_t end = std::min(f.find('\n', start), f.size());
    const std::string_view line = f.substr(start, end - start);
    const std::string_view key = first_field(line);
    if (key == lemma) return line;
    if (key < lemma) lo = end + 1;
    else hi = start;
  }
  return {};
}

std::vector<uint32_t> Database::senses(std::string_view lemma, Pos pos) const {
  const std::vector<std::string_view> f = fields(index_line(lemma, pos));
  // lemma pos synset_cnt p_cnt [ptr_symbol...] sense_cnt tagsense_cnt synset_offset...
  std::vector<uint32_t> out;
  if (f.size() < 4) return out;
  const size_t p_cnt = number(f[3], 10);
  for (size_t i = 6 + p_cnt; i < f.size(); ++i) out.push_back(static_cast<uint32_t>(number(f[i], 10)));
  return out;
}

int Database::tagged_senses(std::string_view lemma, Pos pos) const {
  const std::vector<std::string_view> f = fields(index_line(lemma, pos));
  if (f.size() < 4) return 0;
  const size_t p_cnt = number(f[3], 10);
  return f.size() > 5 + p_cnt ? static_cast<int>(number(f[5 + p_cnt], 10)) : 0;
}

std::optional<Synset> Database::synset(Pos pos, uint32_t offset) const {
  const std::string_view d = data_[static_cast<int>(pos)]->view();
  if (offset >= d.size()) return std::nullopt;
  const size_t end = std::min(d.find('\n', offset), d.size());
  const std::string_view line = d.substr(offset, end - offset);
  // offset lex_filenum ss_type w_cnt(hex) [word lex_id]... p_cnt [symbol offset pos src/tgt]... | gloss
  const std::vector<std::string_view> f = fields(line);
  if (f.size() < 4 || number(f[0], 10) != offset) return std::nullopt;
  Synset s;
  s.offset = offset;
  s.pos = pos;
  s.lex_file = static_cast<int>(number(f[1], 10));
  const size_t w_cnt = number(f[3], 16);
  size_t i = 4;
  for (size_t k = 0; k < w_cnt && i + 1 < f.size(); ++k, i += 2) {
    std::string w = lower(f[i]);
    if (const size_t paren = w.find('('); paren != std::string::npos) w.resize(paren);  // adjective markers "(a)"
    s.words.push_back(std::move(w));
  }
  const size_t p_cnt = i < f.size() ? number(f[i], 10) : 0;
  ++i;
  for (size_t k = 0; k < p_cnt && i + 3 < f.size(); ++k, i += 4)
    s.pointers.push_back({std::string(f[i]), pos_of_char(f[i + 2].empty() ? 'n' : f[i + 2][0]),
                          static_cast<uint32_t>(number(f[i + 1], 10))});
  // A verb's frames: f_cnt [+ f_num w_num]...
  if (pos == Pos::Verb && i < f.size()) {
    const size_t f_cnt = number(f[i], 10);
    ++i;
    for (size_t k = 0; k < f_cnt && i + 2 < f.size() && f[i] == "+"; ++k, i += 3)
      if (const int frame = static_cast<int>(number(f[i + 1], 10)); std::find(s.frames.begin(), s.frames.end(), frame) == s.frames.end())
        s.frames.push_back(frame);
  }
  if (const size_t bar = line.find('|'); bar != std::string_view::npos) {
    std::string_view g = line.substr(bar + 1);
    while (!g.empty() && g.front() == ' ') g.remove_prefix(1);
    while (!g.empty() && g.back() == ' ') g.remove_suffix(1);
    s.gloss = std::string(g);
  }
  return s;
}

std::vector<Ancestor> Database::hypernyms(Pos pos, uint32_t offset, int max_depth) const {
  std::vector<Ancestor> out;
  std::vector<uint32_t> frontier = {offset};
  std::vector<uint32_t> seen = {offset};
  for (int depth = 1; depth <= max_depth && !frontier.empty(); ++depth) {
    std::vector<uint32_t> next;
    for (uint32_t o : frontier) {
      const std::optional<Synset> s = synset(pos, o);
      if (!s) continue;
      for (const Pointer& p : s->pointers) {
        if ((p.symbol != "@" && p.symbol != "@i") || p.pos != pos) continue;
        if (std::find(seen.begin(), seen.end(), p.offset) != seen.end()) continue;
        seen.push_back(p.offset);
        next.push_back(p.offset);
        out.push_back({p.offset, depth});
      }
    }
    frontier = std::move(next);
  }
  return out;
}

std::vector<std::string> Database::base_forms(std::string_view word_in, Pos pos) const {
  std::string word = lower(word_in);
  std::replace(word.begin(), word.end(), ' ', '_');
  std::vector<std::string> out;
  auto add = [&](const std::string& lemma) {
    if (std::find(out.begin(), out.end(), lemma) == out.end() && !senses(lemma, pos).empty()) out.push_back(lemma);
  };
  // A collocation inflects its first word: "takes_off" -> "take_off".
  const size_t us = word.find('_');
  const std::string head = word.substr(0, us), rest = us == std::string::npos ? "" : word.substr(us);
  const auto& exc = exc_->by_pos[static_cast<int>(pos)];
  if (auto it = exc.find(word); it != exc.end())
    for (const auto& b : it->second) add(b);
  if (!rest.empty())
    if (auto it = exc.find(head); it != exc.end())
      for (const auto& b : it->second) add(b + rest);
  add(word);
  // man 7 morphy, "Rules of Detachment".
  static const std::vector<std::pair<std::string, std::string>> kRules[4] = {
      {{"s", ""}, {"ses", "s"}, {"xes", "x"}, {"zes", "z"}, {"ches", "ch"}, {"shes", "sh"}, {"men", "man"}, {"ies", "y"}},
      {{"s", ""}, {"ies", "y"}, {"es", "e"}, {"es", ""}, {"ed", "e"}, {"ed", ""}, {"ing", "e"}, {"ing", ""}},
      {{"er", ""}, {"est", ""}, {"er", "e"}, {"est", "e"}},
      {}};
  for (const auto& [suffix, ending] : kRules[static_cast<int>(pos)]) {
    if (head.size() <= suffix.size() || head.compare(head.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    if (pos == Pos::Noun && suffix == "s" && head.size() > 2 && head.compare(head.size() - 2, 2, "ss") == 0) continue;  // "glass"
    const std::string stem = head.substr(0, head.size() - suffix.size());
    add(stem + ending + rest);
    // Not in morphy, which leaves these to the exception list: a doubled final consonant
    // ("running" -> run, "flapped" -> flap).
    if ((suffix == "ing" || suffix == "ed") && ending.empty() && stem.size() > 2 && stem.back() == stem[stem.size() - 2] &&
        !std::strchr("aeiou", stem.back()))
      add(stem.substr(0, stem.size() - 1) + rest);
  }
  return out;
}

}  // namespace svgm::wordnet
