// The motion lexicon (see lexicon.h): which WordNet synsets the vocabulary's verbs and part
// nouns stand for ("claims"), and the walks up the graph from a new word to the nearest claim.
#include "motion/lexicon.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>

#include "motion/lexicon_anchors.h"
#include "motion/sense_context.h"

namespace svgm {

namespace {

using wordnet::Pos;
using wordnet::Synset;

// Verb senses a vocabulary verb claims: its own name's first kNameSenses senses, each other
// stem's most frequent one, in the lexicographer files of bodily and physical action (man 5
// lexnames: 29 body, 30 change, 32 communication, 34 consumption, 35 contact, 38 motion,
// 39 perception, 43 weather). Farther senses are other meanings ("run a company", "fall
// into a category") whose hyponyms are not motions.
constexpr int kNameSenses = 3;
constexpr int kStemSenses = 1;
constexpr std::array<int, 8> kVerbFiles = {29, 30, 32, 34, 35, 38, 39, 43};
constexpr int kMotionFile = 38, kBodyFile = 29;
// In verb.change only changes of size and shape are motions the vocabulary draws (grow, bend,
// stretch); the rest are becomings ("grow" 1 is "pass into a condition": "he grew angry").
constexpr int kChangeFile = 30;
constexpr std::array<const char*, 2> kDrawnChanges = {"change_magnitude", "change_shape"};
// How far up a verb's graph a claim may be: four steps reach the top of verb.motion ("travel,
// go, move") from most motion verbs; farther is any verb at all.
constexpr int kMaxVerbDepth = 4;
// A later sense costs this many steps per rank ("shorter paths and earlier senses win").
constexpr double kSenseCost = 0.5;
// Part nouns: the first senses of each, in 5 animal, 6 artifact, 8 body, 17 object,
// 19 phenomenon, 20 plant; a new noun reaches one within kMaxPartDepth steps up its
// hypernyms or the wholes it is a part of (finger -> hand).
constexpr int kPartSenses = 3;
constexpr std::array<int, 6> kPartFiles = {5, 6, 8, 17, 19, 20};
constexpr int kMaxPartDepth = 3;
constexpr int kMaxNounDepth = 20;  // deeper than any noun hierarchy in WordNet 3.0 (19)
constexpr int kAnimalFile = 5, kFoodFile = 13, kPersonFile = 18;
// A verb of making a noise: one of its first kSoundSenses senses within kSoundDepth hypernym
// steps of a sound anchor ("hum" 1 is to sing, 2 to make a low sound; "chug" is one step from
// "sound, go"; "crow" 3, to utter shrill sounds, one step from "utter, emit").
constexpr size_t kSoundSenses = 3;
constexpr int kSoundDepth = 2;

template <size_t N>
bool in(const std::array<int, N>& a, int v) { return std::find(a.begin(), a.end(), v) != a.end(); }

// WordNet's sentence frames with no object (man 5 wndb): "Something ----s", "Somebody ----s",
// "It is ----ing", "Something is ----ing PP", "... Adjective", "----s to somebody", "----s on
// something", "Somebody ----s PP", "Somebody's (body part) ----s". A synset with frames and none
// of these only says what its subject does to something else ("move, displace": cause to move;
// "put", "carry", "push" are kinds of it): the one doing it need not move at all.
constexpr std::array<int, 11> kNoObjectFrames = {1, 2, 3, 4, 6, 7, 12, 13, 22, 23, 27};

bool moves_something_else(const Synset& s) {
  return !s.frames.empty() && std::none_of(s.frames.begin(), s.frames.end(), [](int f) { return in(kNoObjectFrames, f); });
}

// A verb whose first action moves the whole figure (a slide, a sway, a spin of its body) says
// how the figure itself moves: it claims no sense that moves something else.
bool moves_whole_figure(const Verb& v) {
  return !v.actions.empty() && (v.actions[0].target == Target::Whole || v.actions[0].target == Target::Root);
}

bool has_pointer(const Synset& s, const char* symbol) {
  return std::any_of(s.pointers.begin(), s.pointers.end(), [&](const wordnet::Pointer& p) { return p.symbol == symbol; });
}

// Lemmas a stem of the table stands for: "wav" -> wave, "flie" -> fly, "run" -> run. When the
// stem and the stem with an "e" are both verbs, the one used more often in WordNet's tagged
// texts, the stem itself on a tie: twinkle's "shin" is shine (to shin up a pole is to climb),
// eat's "sing" is sing (not singe).
std::vector<std::string> stem_lemmas(const wordnet::Database& db, const std::string& stem) {
  std::vector<std::string> out = {stem, stem + "e"};
  if (!db.senses(stem, Pos::Verb).empty() && !db.senses(stem + "e", Pos::Verb).empty())
    out = {db.tagged_senses(stem + "e", Pos::Verb) > db.tagged_senses(stem, Pos::Verb) ? stem + "e" : stem};
  if (stem.size() > 2 && stem.compare(stem.size() - 2, 2, "ie") == 0) out.push_back(stem.substr(0, stem.size() - 2) + "y");
  return out;
}

// Whether a sense of a part noun's lemma means that part: the synset is named by the lemma
// first, or lies in the lexicographer file of the lemma's first sense. "arm" 2 is the synset
// {weapon, arm, weapon_system}: a weapon (a musket ball, a sword) is no arm ("dribbles the
// ball" swung the player's arm); an airplane's {wing} stays a wing.
bool names_it(const Synset& s, const std::string& lemma, int first_file) {
  return (!s.words.empty() && s.words.front() == lemma) || s.lex_file == first_file;
}

}  // namespace

const char* figure_class_name(FigureClass c) {
  static constexpr std::array<const char*, 12> names = {"none",   "biped", "quadruped", "bird",   "fish_or_snake", "insect",
                                                        "plant",  "wheeled", "flame",   "liquid", "object",        "scene"};
  return names[static_cast<size_t>(c)];
}

bool is_creature(FigureClass c) {
  return c == FigureClass::Biped || c == FigureClass::Quadruped || c == FigureClass::Bird || c == FigureClass::FishOrSnake ||
         c == FigureClass::Insect;
}

const Verb* vocabulary_verb(std::string_view word) { return find_verb_by_word(word); }

const Verb* default_verb(FigureClass c) {
  const char* w = class_motion(c);
  return w ? vocabulary_verb(w) : nullptr;
}

Lexicon::Lexicon(const wordnet::Database* db) : db_(db) {
  if (!db_) return;
  claim_verbs();
  claim_parts();
  place_anchors();
}

const Lexicon& Lexicon::shared() {
  static const Lexicon lexicon(wordnet::Database::shared());
  return lexicon;
}

bool Lexicon::is_drawn_change(uint32_t offset) const {
  std::vector<uint32_t> drawn;
  for (const char* lemma : kDrawnChanges)
    for (uint32_t o : db_->senses(lemma, Pos::Verb)) drawn.push_back(o);
  for (const auto& a : db_->hypernyms(Pos::Verb, offset, kMaxVerbDepth + 2))
    if (std::find(drawn.begin(), drawn.end(), a.offset) != drawn.end()) return true;
  return false;
}

void Lexicon::claim_verbs() {
  for (const Verb& v : motion_verbs()) {
    std::vector<std::string> stems = {v.name};
    stems.insert(stems.end(), v.stems.begin(), v.stems.end());
    for (const std::string& stem : stems) {
      // An irregular form ("fell", "sat", "rose") is another verb's inflection, not a lemma.
      if (const auto bases = db_->base_forms(stem, Pos::Verb); !bases.empty() && bases.front() != stem) continue;
      for (const std::string& lemma : stem_lemmas(*db_, stem)) {
        const std::vector<uint32_t> senses = db_->senses(lemma, Pos::Verb);
        // The first senses said of the figure itself: a sense that only moves something else
        // is passed over without counting ("exercise" is first to exert, to practise, to give a
        // workout to someone; its fourth sense, to work out, is the figure's own).
        size_t n = std::min<size_t>(senses.size(), lemma == v.name ? kNameSenses : kStemSenses);
        for (size_t r = 0; r < n; ++r) {
          const std::optional<Synset> s = db_->synset(Pos::Verb, senses[r]);
          if (s && moves_whole_figure(v) && moves_something_else(*s)) {
            n = std::min(n + 1, senses.size());
            continue;
          }
          if (!s || !in(kVerbFiles, s->lex_file)) continue;
          // A root outside verb.motion ("act, move": perform an action) is above every kind of
          // doing; one of verb.body that the verb's own name names first is that motion of the
          // body ("exercise, work out").
          const bool own_body_root = s->lex_file == kBodyFile && !s->words.empty() && s->words.front() == v.name;
          if (s->lex_file != kMotionFile && !own_body_root && !has_pointer(*s, "@")) continue;
          if (s->lex_file == kChangeFile && !is_drawn_change(s->offset)) continue;
          auto& claims = verb_claims_[s->offset];
          if (std::none_of(claims.begin(), claims.end(), [&](const VerbClaim& c) { return c.verb == &v; }))
            claims.push_back({&v, lemma});
        }
      }
    }
  }
}

void Lexicon::claim_parts() {
  for (const PartNoun& p : part_nouns())
    for (const std::string& lemma : {p.stem, p.stem + "e", p.stem + "es"}) {
      const std::vector<uint32_t> senses = db_->senses(lemma, Pos::Noun);
      const std::optional<Synset> first = senses.empty() ? std::nullopt : db_->synset(Pos::Noun, senses.front());
      const int first_file = first ? first->lex_file : -1;
      for (size_t r = 0; r < std::min<size_t>(senses.size(), kPartSenses); ++r)
        if (const auto s = db_->synset(Pos::Noun, senses[r]); s && in(kPartFiles, s->lex_file) && names_it(*s, lemma, first_file))
          part_claims_.emplace(s->offset, &p);
    }
}

void Lexicon::place_anchors() {
  for (const VerbSenseAnchor& a : verb_sense_anchors()) {
    const std::vector<uint32_t> senses = db_->senses(a.lemma, Pos::Verb);
    const Verb* v = vocabulary_verb(a.motion);
    if (!v || a.sense < 1 || static_cast<size_t>(a.sense) > senses.size()) continue;
    auto& claims = verb_claims_[senses[a.sense - 1]];
    if (std::none_of(claims.begin(), claims.end(), [&](const VerbClaim& c) { return c.verb == v; })) claims.push_back({v, a.lemma});
  }
  for (const VerbSense& a : sound_anchors()) {
    const std::vector<uint32_t> senses = db_->senses(a.lemma, Pos::Verb);
    if (a.sense >= 1 && static_cast<size_t>(a.sense) <= senses.size()) sound_roots_.push_back(senses[a.sense - 1]);
  }
  for (const svgm::NounAnchor& a : noun_anchors()) {
    const std::vector<uint32_t> senses = db_->senses(a.lemma, Pos::Noun);
    if (a.sense >= 1 && static_cast<size_t>(a.sense) <= senses.size())
      noun_anchors_.emplace(senses[a.sense - 1], NounPlace{a.figure, a.motion});
  }
}

bool Lexicon::noun_is_animal_word(std::string_view word) const {
  if (!db_) return false;
  for (const std::string& lemma : db_->base_forms(word, Pos::Noun))
    for (uint32_t sense : db_->senses(lemma, Pos::Noun))
      if (const auto s = db_->synset(Pos::Noun, sense); s && s->lex_file == kAnimalFile) return true;
  return false;
}

bool Lexicon::is_sound_verb(std::string_view word) const {
  if (!db_) return false;
  const std::vector<std::string> lemmas = db_->base_forms(word, Pos::Verb);
  if (lemmas.empty()) return false;
  const std::vector<uint32_t> senses = db_->senses(lemmas.front(), Pos::Verb);
  bool sound = false;
  for (size_t r = 0; r < std::min<size_t>(senses.size(), kSoundSenses); ++r) {
    const std::optional<Synset> s = db_->synset(Pos::Verb, senses[r]);
    if (!s) continue;
    if (s->lex_file == kMotionFile) return false;
    std::vector<uint32_t> up = {senses[r]};
    for (const auto& a : db_->hypernyms(Pos::Verb, senses[r], kSoundDepth)) up.push_back(a.offset);
    for (uint32_t o : up) sound = sound || std::find(sound_roots_.begin(), sound_roots_.end(), o) != sound_roots_.end();
  }
  return sound;
}

bool Lexicon::knows_verb(std::string_view word) const { return db_ && !db_->base_forms(word, Pos::Verb).empty(); }
bool Lexicon::knows_noun(std::string_view word) const { return db_ && !db_->base_forms(word, Pos::Noun).empty(); }

int Lexicon::tagged_senses(std::string_view word, Pos pos) const {
  if (!db_) return 0;
  const std::vector<std::string> lemmas = db_->base_forms(word, pos);
  return lemmas.empty() ? 0 : db_->tagged_senses(lemmas.front(), pos);
}

VerbReading Lexicon::verb(std::string_view word) const {
  if (!db_) return {};
  return verb_from_lemmas(db_->base_forms(word, Pos::Verb));
}

VerbReading Lexicon::phrasal_verb(std::string_view word, std::string_view particle) const {
  if (!db_) return {};
  return verb_from_lemmas(db_->base_forms(std::string(word) + "_" + std::string(particle), Pos::Verb));
}

VerbReading Lexicon::verb_from_lemmas(const std::vector<std::string>& lemmas) const {
  VerbReading best;
  for (const std::string& lemma : lemmas)
    for (const VerbAnchor& a : verb_anchors())
      if (lemma == a.lemma) return {vocabulary_verb(a.motion), "anchor", 0};
  double best_score = 1e9;
  for (const std::string& lemma : lemmas) {
    const std::vector<uint32_t> senses = db_->senses(lemma, Pos::Verb);
    for (size_t rank = 0; rank < senses.size(); ++rank) {
      // Breadth first up hypernyms, verb groups (near-synonyms) and entailments ("snore"
      // entails "sleep"); the first level holding a claimed synset ends this sense's walk.
      std::vector<uint32_t> frontier = {senses[rank]}, seen = frontier;
      for (int depth = 0; depth <= kMaxVerbDepth && !frontier.empty(); ++depth) {
        const double score = depth + kSenseCost * static_cast<double>(rank);
        if (score >= best_score) break;
        std::vector<uint32_t> next;
        bool hit = false;
        for (uint32_t o : frontier) {
          const std::optional<Synset> s = db_->synset(Pos::Verb, o);
          if (!s) continue;
          if (auto it = verb_claims_.find(o); it != verb_claims_.end() && !hit) {
            // Several verbs claim it: the one whose name it lists first, else whose stem.
            const VerbClaim* pick = &it->second.front();
            std::string word = pick->lemma;
            size_t at = SIZE_MAX;
            for (const VerbClaim& c : it->second)
              for (size_t w = 0; w < s->words.size(); ++w) {
                const size_t key = s->words[w] == c.verb->name ? w : s->words[w] == c.lemma ? s->words.size() + w : SIZE_MAX;
                if (key < at) at = key, pick = &c, word = s->words[w];
              }
            best = {pick->verb, word, depth};
            best_score = score;
            hit = true;
          }
          for (const wordnet::Pointer& p : s->pointers)
            if (p.pos == Pos::Verb && (p.symbol == "@" || p.symbol == "$" || p.symbol == "*") &&
                std::find(seen.begin(), seen.end(), p.offset) == seen.end()) {
              seen.push_back(p.offset);
              next.push_back(p.offset);
            }
        }
        if (hit) break;
        frontier = std::move(next);
      }
    }
  }
  if (best.verb) return best;
  // No motion above it: a verb made from a noun that moves by itself ("smoke" -> smoke rises,
  // "blaze" -> fire flickers) moves as that noun does; only fire, water and the motion-only
  // anchors (a verb made from an animal or a person, "to man", "to dog", is no such motion).
  for (const std::string& lemma : lemmas) {
    const std::vector<uint32_t> senses = db_->senses(lemma, Pos::Verb);
    for (size_t rank = 0; rank < std::min<size_t>(senses.size(), 2); ++rank) {
      const std::optional<Synset> s = db_->synset(Pos::Verb, senses[rank]);
      if (!s) continue;
      for (const wordnet::Pointer& p : s->pointers) {
        if (p.symbol != "+" || p.pos != Pos::Noun) continue;
        // The noun synset itself or one of its hypernyms carrying a motion anchor.
        std::vector<uint32_t> chain = {p.offset};
        for (const auto& a : db_->hypernyms(Pos::Noun, p.offset, kMaxNounDepth)) chain.push_back(a.offset);
        for (uint32_t o : chain)
          if (auto it = noun_anchors_.find(o); it != noun_anchors_.end() && it->second.motion &&
              (it->second.figure == FigureClass::None || it->second.figure == FigureClass::Flame ||
               it->second.figure == FigureClass::Liquid))
            return {vocabulary_verb(it->second.motion), db_->synset(Pos::Noun, o)->words.front(), 0};
      }
    }
  }
  return {};
}

FigureClass Lexicon::sense_class(uint32_t sense) const {
  std::vector<uint32_t> chain = {sense};
  for (const auto& a : db_->hypernyms(Pos::Noun, sense, kMaxNounDepth)) chain.push_back(a.offset);
  for (uint32_t o : chain)
    if (const auto it = noun_anchors_.find(o); it != noun_anchors_.end() && it->second.figure != FigureClass::None) return it->second.figure;
  return FigureClass::None;
}

std::vector<uint32_t> Lexicon::noun_senses(const std::string& lemma) const {
  const std::vector<uint32_t> senses = db_->senses(lemma, Pos::Noun);
  const int tagged = db_->tagged_senses(lemma, Pos::Noun);
  struct Sense {
    uint32_t offset;
    int rank, lex_file;
    bool clipped;
    bool named_first;  // the synset's first word is the lemma (not another name it goes by)
  };
  std::vector<Sense> order;
  for (size_t r = 0; r < senses.size(); ++r) {
    const std::optional<Synset> s = db_->synset(Pos::Noun, senses[r]);
    if (!s) continue;
    // A synset listing a longer word that starts with the lemma names that thing by its first
    // word ("turtle" for turtleneck, "peacock" for peacock_butterfly): the lemma's own meaning
    // comes first. Not a phrase whose first word is an adjective ("herbaceous plant" beside
    // "herb" is the herb itself: taken for a clipping, a herb was the potherb, a food).
    const bool clipped = std::any_of(s->words.begin(), s->words.end(), [&](const std::string& w) {
      if (w.size() <= lemma.size() || w.compare(0, lemma.size(), lemma) != 0) return false;
      const std::string first = w.substr(0, w.find('_'));
      return first == lemma || db_->senses(first, Pos::Adj).empty();
    });
    order.push_back({senses[r], static_cast<int>(r), s->lex_file, clipped, !s->words.empty() && s->words.front() == lemma});
  }
  std::stable_partition(order.begin(), order.end(), [](const Sense& s) { return !s.clipped; });
  // An animal comes before the senses ahead of it that are people ("whale", "snake", "crab"
  // said of a person are figures of speech), food made of it ("octopus") or not ranked by
  // tagged frequency at all ("seal": eight artifacts first, in no meaningful order).
  // Not an animal sense the anchors class as no creature: "baby" 6, a young mammal, is filed
  // under "young" apart from the mammals (an object), and the infant of the first sense, a person,
  // was read so.
  // With no sense ranked, a vehicle (the anchors' wheeled) the lemma names first is its own
  // meaning, before those that list it as another name ("scooter": the kick scooter before the
  // water scooter, the motor scooter, the iceboat and the scoter, a duck). Only a vehicle: every
  // unranked word's own senses first read "stalk" as a plant's stem, not chaff, and its bend changed.
  if (tagged == 0)
    std::stable_partition(order.begin(), order.end(), [&](const Sense& s) { return !s.clipped && s.named_first && sense_class(s.offset) == FigureClass::Wheeled; });
  // Nor ahead of a vehicle (the anchors' wheeled) of the same word with no rank: it is no figure
  // of speech. "scooter" is also the scoter: moved ahead of the scooters, a scooter was read as
  // a bird.
  for (size_t i = 0; i < order.size(); ++i) {
    if (order[i].lex_file != kAnimalFile || !is_creature(sense_class(order[i].offset))) continue;
    const bool before_ok = std::all_of(order.begin(), order.begin() + static_cast<long>(i), [&](const Sense& s) {
      return s.lex_file == kPersonFile || s.lex_file == kFoodFile || (s.rank >= tagged && sense_class(s.offset) != FigureClass::Wheeled);
    });
    if (before_ok) std::rotate(order.begin(), order.begin() + static_cast<long>(i), order.begin() + static_cast<long>(i) + 1);
    break;
  }
  std::vector<uint32_t> out;
  for (const Sense& s : order) out.push_back(s.offset);
  return out;
}

NounReading Lexicon::noun(std::string_view word, const std::vector<std::string>& context) const {
  NounReading r;
  if (!db_) return r;
  const std::vector<std::string> lemmas = db_->base_forms(word, Pos::Noun);
  // The class: the first sense (noun_senses' order) with an anchor up its hypernyms; the
  // nearest anchor gives the class, the nearest with a motion the motion.
  for (const std::string& lemma : lemmas) {
    std::string why;
    const std::vector<uint32_t> ordered = senses_by_context(*db_, lemma, noun_senses(lemma), context, &why);
    for (uint32_t sense : ordered) {
      std::vector<uint32_t> chain = {sense};
      for (const auto& a : db_->hypernyms(Pos::Noun, sense, kMaxNounDepth)) chain.push_back(a.offset);
      const char* motion = nullptr;
      for (uint32_t o : chain) {
        const auto it = noun_anchors_.find(o);
        if (it == noun_anchors_.end()) continue;
        if (!motion && it->second.motion) motion = it->second.motion;
        if (r.figure == FigureClass::None && it->second.figure != FigureClass::None) {
          r.figure = it->second.figure;
          r.via = db_->synset(Pos::Noun, o)->words.front();
        }
      }
      if (r.figure == FigureClass::None) continue;
      if (sense == ordered.front() && !why.empty()) r.sense_why = why;
      if (motion) {
        r.motion = vocabulary_verb(motion);
        r.motion_word = motion;
      }
      break;
    }
    if (r.figure != FigureClass::None) break;
  }
  // The part: up hypernyms and the wholes it is a part of, the nearest claim (a later sense
  // costing kSenseCost a rank).
  double best = 1e9;
  for (const std::string& lemma : lemmas) {
    const std::vector<uint32_t> senses = db_->senses(lemma, Pos::Noun);
    for (size_t rank = 0; rank < std::min<size_t>(senses.size(), kPartSenses); ++rank) {
      std::vector<uint32_t> frontier = {senses[rank]}, seen = frontier;
      for (int depth = 0; depth <= kMaxPartDepth && !frontier.empty(); ++depth) {
        const double score = depth + kSenseCost * static_cast<double>(rank);
        if (score >= best) break;
        std::vector<uint32_t> next;
        for (uint32_t o : frontier) {
          if (auto it = part_claims_.find(o); it != part_claims_.end() && score < best) {
            r.part = it->second;
            best = score;
          }
          if (const std::optional<Synset> s = db_->synset(Pos::Noun, o))
            for (const wordnet::Pointer& p : s->pointers)
              if (p.pos == Pos::Noun && (p.symbol == "@" || p.symbol == "#p") &&
                  std::find(seen.begin(), seen.end(), p.offset) == seen.end()) {
                seen.push_back(p.offset);
                next.push_back(p.offset);
              }
        }
        if (score >= best) break;
        frontier = std::move(next);
      }
    }
  }
  return r;
}

}  // namespace svgm
