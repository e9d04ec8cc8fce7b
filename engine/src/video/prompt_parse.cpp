// Prompt clauses and explicit plans (see prompt_parse.h).
#include "video/prompt_parse.h"

#include <algorithm>
#include <cctype>

#include "svgmotion/error.h"

namespace svgm {

namespace {

std::string lower(const std::string& s) {
  std::string r;
  for (char c : s) r += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

bool is_conjunction(const std::string& w) {
  return w == "and" || w == "while" || w == "whilst" || w == "then" || w == "as" || w == "but" ||
         w == "before" || w == "after";
}

bool is_preposition(const std::string& w) {
  static const std::vector<std::string> p = {"on", "onto", "in", "into", "at", "over", "under", "from", "to",
                                             "through", "across", "against", "above", "below", "behind", "near",
                                             "of", "with", "by", "toward", "towards", "past", "beside", "off"};
  return std::find(p.begin(), p.end(), w) != p.end();
}

bool is_determiner(const std::string& w) {
  return w == "the" || w == "a" || w == "an" || w == "its" || w == "his" || w == "her" || w == "their" || w == "my" ||
         w == "your" || w == "our";
}

const Verb* verb_for_word(const std::string& w) {
  for (const auto& v : motion_verbs())
    for (const auto& s : v.stems)
      if (word_matches(w, s)) return &v;
  return nullptr;
}

// "surfer", "runners", "biker", "rider": a verb with the agent ending ("er" after a stem, which
// word_matches reads as an inflection; "r" after a verb's word ending in "e").
bool is_agent_noun(const std::string& w) {
  const std::string one = w.size() > 1 && w.back() == 's' ? w.substr(0, w.size() - 1) : w;
  if (one.size() < 5 || one.compare(one.size() - 2, 2, "er") != 0) return false;
  return verb_for_word(one) || verb_for_word(one.substr(0, one.size() - 1));
}

const PartNoun* noun_for_word(const std::string& w) {
  for (const auto& n : part_nouns())
    if (word_matches(w, n.stem) || (n.stem == "leaf" && w == "leaves")) return &n;
  return nullptr;
}

// Words of one clause (lower case, letters only). `after_prep` says the clause continues a
// prepositional phrase ("with black dots and black boots": "and" split it, and "boots" is
// still what she is dressed with); on return, whether the clause ends inside one.
Clause read_clause(const std::vector<std::string>& words, bool& after_prep) {
  Clause c;
  std::string prev;
  for (size_t wi = 0; wi < words.size(); ++wi) {
    const std::string& w = words[wi];
    const bool prev_was_start = c.text.empty();
    c.text += (c.text.empty() ? "" : " ") + w;
    const bool after_determiner = is_determiner(prev);
    prev = w;
    if (Modifiers probe = c.mods; apply_modifier(w, probe)) {
      c.mods = probe;
      continue;
    }
    // A known part noun is a noun even where its word could be a verb ("drops", "hands").
    if (const PartNoun* n = noun_for_word(w)) {
      const bool plural = (w.size() > n->stem.size() && w.back() == 's') || w == "feet" || w == "leaves";
      c.nouns.push_back({w, n->target, plural, after_prep, !c.verbs.empty()});
      after_prep = false;
      continue;
    }
    // A verb's agent noun opening the clause or after an article ("a surfer rides", "the
    // biker is pedalling") is the one who moves: the whole figure, not a part named like it (a
    // surfer's shadow drawn as "shadow_surfer" swung while the surfer stood still).
    if ((prev_was_start || after_determiner) && is_agent_noun(w)) continue;
    // A verb's word right after an article or a possessive is a noun ("rides the waves",
    // "in the breeze"), unless it is a participle ("a galloping horse", "a waving flag").
    const bool participle = w.size() > 4 && w.compare(w.size() - 3, 3, "ing") == 0;
    // ... and so is one right before a verb that says what it does ("the cobra snake sways": the
    // snake is who sways, it does not slither): a bare word followed by another verb's word
    // in the third person ("sways", not "swaying"). Two words of one verb say it once ("rain
    // falls").
    const std::string next = wi + 1 < words.size() ? words[wi + 1] : std::string();
    const bool bare = w.back() != 's' && !participle && !(w.size() > 3 && w.compare(w.size() - 2, 2, "ed") == 0);
    const Verb* next_verb = next.size() > 3 && next.back() == 's' && next[next.size() - 2] != 's' ? verb_for_word(next) : nullptr;
    const bool subject = bare && next_verb && next_verb != verb_for_word(w);
    const Verb* v = (after_determiner && !participle) || subject ? nullptr : verb_for_word(w);
    if (v) {
      if (std::find(c.verbs.begin(), c.verbs.end(), v) == c.verbs.end()) {
        c.verbs.push_back(v);
        c.verb_words.push_back(w);
      }
      after_prep = false;
      continue;
    }
    if (is_preposition(w)) { after_prep = true; continue; }
    if (is_filler_word(w)) continue;
    c.nouns.push_back({w, Target::Named, w.size() > 3 && w.back() == 's', after_prep, !c.verbs.empty()});
  }
  return c;
}

// A verbless clause saying something of its nouns with a past participle the vocabulary does
// not know ("its hood slightly flared", "her eyes closed"): the unknown words are kept as
// nouns by read_clause, a participle among them ends in "ed".
bool has_unknown_participle(const Clause& c) {
  if (!c.verbs.empty()) return false;
  for (const auto& n : c.nouns)
    if (n.target == Target::Named && n.word.size() > 4 && n.word.compare(n.word.size() - 2, 2, "ed") == 0) return true;
  return false;
}

void merge_into(Clause& into, Clause from) {
  // Its nouns are described by the participle: not the targets of the verb it joins.
  if (has_unknown_participle(from))
    for (auto& n : from.nouns) n.own_predicate = true;
  into.text += " " + from.text;
  for (size_t i = 0; i < from.verbs.size(); ++i)
    if (std::find(into.verbs.begin(), into.verbs.end(), from.verbs[i]) == into.verbs.end()) {
      into.verbs.push_back(from.verbs[i]);
      into.verb_words.push_back(from.verb_words[i]);
    }
  into.nouns.insert(into.nouns.end(), from.nouns.begin(), from.nouns.end());
  for (const auto& w : from.mods.words) apply_modifier(w, into.mods);
}

}  // namespace

ParsedPrompt parse_prompt(const std::string& prompt) {
  // Split into raw clauses of words.
  std::vector<std::vector<std::string>> raw(1);
  std::vector<char> after_and(1, 0);  // per raw clause: split from the one before by "and"
  std::string word;
  auto flush = [&] {
    if (word.empty()) return;
    if (is_conjunction(word)) {
      if (!raw.back().empty()) {
        raw.emplace_back();
        after_and.push_back(word == "and");
      }
    } else {
      raw.back().push_back(word);
    }
    word.clear();
  };
  for (char ch : lower(prompt)) {
    if (std::isalpha(static_cast<unsigned char>(ch))) {
      word += ch;
      continue;
    }
    flush();
    if (ch == ',' || ch == '.' || ch == ';' || ch == ':' || ch == '!' || ch == '?')
      if (!raw.back().empty()) {
        raw.emplace_back();
        after_and.push_back(0);
      }
  }
  flush();
  ParsedPrompt out;
  std::vector<Clause> clauses;
  bool prep_open = false;  // the clause before ended inside a prepositional phrase, with no verb
  for (size_t i = 0; i < raw.size(); ++i) {
    if (raw[i].empty()) continue;
    bool after_prep = prep_open && after_and[i];
    clauses.push_back(read_clause(raw[i], after_prep));
    prep_open = after_prep && clauses.back().verbs.empty();
  }
  // A clause without a verb joins the one before it (or, first in the prompt, the one after).
  for (const Clause& c : clauses) {
    if (!out.clauses.empty() && (c.verbs.empty() || out.clauses.back().verbs.empty()))
      merge_into(out.clauses.back(), c);
    else
      out.clauses.push_back(c);
  }
  return out;
}

bool glob_match(const std::string& pattern, const std::string& text) {
  const std::string p = lower(pattern), t = lower(text);
  // Iterative '*' matching with backtracking to the last star.
  size_t pi = 0, ti = 0, star = std::string::npos, mark = 0;
  while (ti < t.size()) {
    if (pi < p.size() && p[pi] == t[ti]) { ++pi; ++ti; }
    else if (pi < p.size() && p[pi] == '*') { star = pi++; mark = ti; }
    else if (star != std::string::npos) { pi = star + 1; ti = ++mark; }
    else return false;
  }
  while (pi < p.size() && p[pi] == '*') ++pi;
  return pi == p.size();
}

std::vector<ExplicitStep> parse_explicit_plan(const std::string& text) {
  std::vector<ExplicitStep> steps;
  std::string item;
  auto finish = [&] {
    std::string s = item;
    item.clear();
    // Trim.
    const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    if (a == std::string::npos) throw Error("motion plan '" + text + "': an empty item");
    s = s.substr(a, b - a + 1);
    ExplicitStep step;
    std::vector<std::string> tokens;
    for (size_t at = 0; at < s.size();) {
      const size_t sp = s.find_first_of(" \t", at);
      const std::string tok = s.substr(at, sp == std::string::npos ? std::string::npos : sp - at);
      if (!tok.empty()) tokens.push_back(tok);
      if (sp == std::string::npos) break;
      at = sp + 1;
    }
    const std::string head = tokens.front();
    const size_t colon = head.find(':');
    step.verb = lower(head.substr(0, colon));
    if (!find_verb_by_name(step.verb)) {
      std::string names;
      for (const auto& v : motion_verbs()) names += (names.empty() ? "" : ", ") + v.name;
      throw Error("motion plan '" + s + "': unknown verb '" + step.verb + "' (verbs: " + names + ")");
    }
    if (colon != std::string::npos) {
      const std::string pats = head.substr(colon + 1);
      size_t at = 0;
      while (at <= pats.size()) {
        const size_t plus = pats.find('+', at);
        const std::string p = pats.substr(at, plus == std::string::npos ? std::string::npos : plus - at);
        if (p.empty()) throw Error("motion plan '" + s + "': an empty part pattern");
        step.patterns.push_back(p);
        if (plus == std::string::npos) break;
        at = plus + 1;
      }
    }
    for (size_t i = 1; i < tokens.size(); ++i)
      if (!apply_modifier(lower(tokens[i]), step.mods))
        throw Error("motion plan '" + s + "': unknown modifier '" + tokens[i] +
                    "' (modifiers: slow, fast, gently, wildly, once, repeatedly, left, right, up, down, both)");
    steps.push_back(std::move(step));
  };
  for (char ch : text) {
    if (ch == ',' || ch == ';') finish();
    else item += ch;
  }
  finish();
  return steps;
}

}  // namespace svgm
