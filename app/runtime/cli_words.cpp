#include "app/runtime/cli_words.h"

#include <algorithm>
#include <cctype>

namespace rs4sim::app {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string in_quotes(std::string_view s) { return "'" + std::string(s) + "'"; }

// The command a parse error belongs to: "rs4sim run", "rs4sim archive list".
const CLI::App* deepest_parsed(const CLI::App* app) {
  const auto parsed = app->get_subcommands();
  return parsed.empty() ? app : deepest_parsed(parsed.front());
}

std::string command_path(const CLI::App* app) {
  std::string path;
  for (const CLI::App* a = app; a != nullptr; a = a->get_parent()) {
    const std::string name = a->get_parent() == nullptr ? "rs4sim" : a->get_name();
    path = path.empty() ? name : name + " " + path;
  }
  return path;
}

// Every long and short option name of `app` with its dashes, --help included.
std::vector<std::string> option_names(const CLI::App* app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app->get_options()) {
    for (const auto& l : o->get_lnames()) names.push_back("--" + l);
    for (const auto& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

// The words the parser left over, one sentence each.
std::string left_over(const CLI::App* app) {
  const std::string path = command_path(app);
  std::string text;
  const auto options = option_names(app);
  std::vector<std::string> commands;
  for (const CLI::App* s : app->get_subcommands([](const CLI::App*) { return true; })) {
    commands.push_back(s->get_name());
  }
  bool option_before = false;  // a word right after an unknown option is taken for its value
  for (const std::string& word : app->remaining()) {
    const bool option = word.size() > 1 && word[0] == '-';
    std::optional<std::string> near;
    if (option) {
      const std::string name = word.substr(0, word.find('='));
      text += path + ": unknown option " + name;
      near = did_you_mean(name, options);
    } else if (!option_before) {
      text += path + ": unexpected argument " + in_quotes(word);
      near = did_you_mean(word, commands);
    }
    if (near) text += " (did you mean " + *near + "?)";
    if (option || !option_before) text += "\n";
    option_before = option;
  }
  return text + path + " --help lists its options\n";
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment: insert, delete, substitute, or swap two neighbours, each 1.
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

std::optional<std::string> did_you_mean(std::string_view word,
                                        const std::vector<std::string>& candidates) {
  const std::string w = lower(word);
  std::optional<std::string> best;
  std::size_t best_distance = 0;
  std::vector<const std::string*> prefixed;
  for (const auto& c : candidates) {
    const std::string lc = lower(c);
    if (lc == w) return c;
    if (w.size() >= 3 && lc.rfind(w, 0) == 0) prefixed.push_back(&c);
    const std::size_t d = edit_distance(w, lc);
    const std::size_t longer = std::max(w.size(), lc.size());
    const std::size_t allowed = std::max<std::size_t>(1, std::min<std::size_t>(2, longer / 3));
    if (d <= allowed && (!best || d < best_distance)) {
      best = c;
      best_distance = d;
    }
  }
  if (!best && prefixed.size() == 1) best = *prefixed.front();
  return best;
}

std::string word_list(const std::vector<std::string>& words) {
  std::string s;
  for (std::size_t i = 0; i < words.size(); ++i) {
    s += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  }
  return s;
}

std::string not_one_of(std::string_view value, std::string_view what,
                       const std::vector<std::string>& words) {
  std::string s = in_quotes(value) + " is not " + std::string(what) + "; use " + word_list(words);
  if (const auto near = did_you_mean(value, words)) s += " (did you mean " + in_quotes(*near) + "?)";
  return s;
}

CLI::Validator one_of(std::string what, std::vector<std::string> words) {
  std::string shown;
  for (const auto& w : words) shown += (shown.empty() ? "" : "|") + w;
  return CLI::Validator(
      [what = std::move(what), words = std::move(words)](std::string& value) -> std::string {
        if (std::find(words.begin(), words.end(), value) != words.end()) return {};
        return not_one_of(value, what, words);
      },
      shown);
}

CLI::Validator one_of_index(std::string what, std::vector<std::string> words) {
  std::string shown;
  for (const auto& w : words) shown += (shown.empty() ? "" : "|") + w;
  return CLI::Validator(
      [what = std::move(what), words = std::move(words)](std::string& value) -> std::string {
        const auto it = std::find(words.begin(), words.end(), value);
        if (it == words.end()) return not_one_of(value, what, words);
        value = std::to_string(it - words.begin());
        return {};
      },
      shown);
}

std::string usage_failure(const CLI::App* top, const CLI::Error& e) {
  const CLI::App* app = deepest_parsed(top);
  if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr && !app->remaining().empty()) {
    return left_over(app);
  }
  return command_path(app) + ": " + e.what() + "\n" + command_path(app) +
         " --help lists its options\n";
}

std::string unknown_command(std::string_view word, const std::vector<std::string>& commands) {
  std::string s = "rs4sim: unknown command " + in_quotes(word);
  if (const auto near = did_you_mean(word, commands)) s += " (did you mean " + in_quotes(*near) + "?)";
  std::string names;
  for (const auto& c : commands) names += (names.empty() ? "" : ", ") + c;
  return s + "; the commands are " + names + " (rs4sim --help)";
}

}  // namespace rs4sim::app
