// The figure's class from the document's own names (figure_class.h): a keyword check over the
// words of ids, labels and group names. A stand-in for the prompt's lexicon, which knows far
// more nouns: here only words that name a kind of figure or a part only that kind has
// ("wheel", "wing", "fin", "petal"). Each name votes once for each class it names; the class
// with the most votes wins, ties to the earlier class in the table's order.
#include <array>
#include <cctype>
#include <string_view>

#include "motion/figure_class.h"

namespace svgm::motion {

namespace {

struct Keywords {
  FigureClass cls;
  std::array<std::string_view, 24> words;
};

// Singular forms; a trailing "s" is dropped before the look-up.
constexpr std::array<Keywords, 7> kTable = {{
    {FigureClass::Wheeled, {"wheel", "tire", "tyre", "car", "bus", "truck", "bike", "bicycle", "tractor", "train",
                            "tram", "van", "cart", "wagon", "scooter", "motorcycle", "vehicle", "taxi", "locomotive",
                            "skateboard", "automobile", "ambulance", "lorry", "trolley"}},
    {FigureClass::Bird, {"bird", "wing", "beak", "feather", "eagle", "owl", "duck", "chicken", "rooster", "parrot",
                         "dove", "swan", "flamingo", "peacock", "penguin", "turkey", "hen", "chick", "crow", "goose",
                         "pigeon", "sparrow", "hawk", "bat"}},
    {FigureClass::FishOrSnake, {"fish", "fin", "snake", "eel", "worm", "whale", "dolphin", "shark", "serpent",
                                "tadpole", "caterpillar", "seal"}},
    {FigureClass::Plant, {"plant", "tree", "leaf", "leave", "flower", "petal", "stem", "trunk", "cactus", "palm",
                          "herb", "grass", "rose", "tulip", "blossom", "seedling", "clover", "shamrock", "bush",
                          "branch", "sprout", "hibiscus", "lotus", "fern"}},
    {FigureClass::Quadruped, {"dog", "cat", "horse", "cow", "pig", "sheep", "goat", "deer", "fox", "wolf", "lion",
                              "tiger", "bear", "elephant", "giraffe", "zebra", "camel", "rabbit", "mouse", "rat",
                              "leopard", "paw", "hoof", "mane"}},
    {FigureClass::Biped, {"person", "man", "woman", "boy", "girl", "child", "baby", "human", "people", "player",
                          "runner", "dancer", "arm", "hand", "torso", "robot", "kid", "lady", "guy", "body",
                          "astronaut", "worker", "king", "queen"}},
    {FigureClass::Scene, {"background", "sky", "landscape", "scene", "scenery", "sea", "mountain", "horizon", "city",
                          "sunset", "sunrise", "", "", "", "", "", "", "", "", "", "", "", "", ""}},
}};

std::vector<std::string> words_of(const std::string& name) {
  std::vector<std::string> out;
  std::string w;
  auto flush = [&] {
    if (w.size() > 3 && w.back() == 's') w.pop_back();
    if (!w.empty()) out.push_back(w);
    w.clear();
  };
  for (size_t i = 0; i < name.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    if (std::isalpha(c)) {
      if (std::isupper(c) && !w.empty() && std::islower(static_cast<unsigned char>(name[i - 1]))) flush();  // camelCase
      w += static_cast<char>(std::tolower(c));
    } else {
      flush();
    }
  }
  flush();
  return out;
}

}  // namespace

std::optional<ClassHint> class_from_names(const std::vector<std::string>& names) {
  std::array<int, kTable.size()> votes{};
  for (const auto& name : names) {
    const auto words = words_of(name);
    for (size_t k = 0; k < kTable.size(); ++k) {
      bool hit = false;
      for (const auto& w : words)
        for (const auto& key : kTable[k].words) hit |= !key.empty() && w == key;
      votes[k] += hit;
    }
  }
  size_t best = 0;
  for (size_t k = 1; k < kTable.size(); ++k)
    if (votes[k] > votes[best]) best = k;
  if (votes[best] == 0) return std::nullopt;
  return ClassHint{kTable[best].cls, 0.6};  // a name is the author's word, but may name a part
}

}  // namespace svgm::motion
