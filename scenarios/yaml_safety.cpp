#include "scenarios/yaml_safety.hpp"

#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include "io/text.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/yaml_reader.hpp"

namespace sreh::detail {
namespace {

constexpr const char* kCore = "tag:yaml.org,2002:";

SourceLoc at(const std::string& file, const YAML::Mark& m) {
  return m.is_null() ? SourceLoc{file, 0, 0} : SourceLoc{file, m.line + 1, m.column + 1};
}

class Guard : public YAML::EventHandler {
 public:
  Guard(const std::string& file, const Limits& limits) : file_(file), limits_(limits) {}

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ > 1) {
      fail(mark, "a second YAML document ('---'); a scenario is one document");
    }
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const auto it = size_.find(anchor);
    add(mark, it == size_.end() ? 1.0 : it->second);
  }
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override {
    check_scalar_tag(mark, tag, value);
    leaf(mark, anchor);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, tag, anchor, "seq", "a list");
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, tag, anchor, "map", "a mapping");
  }
  void OnMapEnd() override { close(); }

 private:
  struct Open {
    YAML::anchor_t anchor;
    double nodes_before; // total when it opened
  };

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& what) const {
    throw ScenarioError(at(file_, mark), what);
  }

  // Counts `n` nodes (one node, or a whole aliased subtree) towards the total.
  void add(const YAML::Mark& mark, double n) {
    total_ += n;
    if (total_ > static_cast<double>(limits_.max_yaml_nodes)) {
      fail(mark, fmt::format("more than {} YAML nodes once aliases are expanded (an alias bomb?); "
                             "raise the limit with --max-yaml-nodes", limits_.max_yaml_nodes));
    }
  }

  void leaf(const YAML::Mark& mark, YAML::anchor_t anchor) {
    add(mark, 1);
    if (anchor != YAML::NullAnchor) size_[anchor] = 1;
  }

  void open(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor, const char* core, const char* what) {
    if (tag != "?" && tag != "!" && tag != std::string(kCore) + core) {
      fail(mark, fmt::format("tag '{}' on {} is not supported (plain YAML only; core tags must match the value)",
                             io::escape_control(tag), what));
    }
    if (static_cast<int>(stack_.size()) >= limits_.max_yaml_depth) {
      fail(mark, fmt::format("nesting depth exceeded: more than {} nested lists / mappings; "
                             "raise the limit with --max-yaml-depth", limits_.max_yaml_depth));
    }
    add(mark, 1);
    stack_.push_back(Open{anchor, total_ - 1});
  }

  void close() {
    const Open o = stack_.back();
    stack_.pop_back();
    if (o.anchor != YAML::NullAnchor) size_[o.anchor] = total_ - o.nodes_before;
  }

  void check_scalar_tag(const YAML::Mark& mark, const std::string& tag, const std::string& value) const {
    if (tag == "?" || tag == "!" || tag == std::string(kCore) + "str") return;
    bool ok = false;
    if (tag == std::string(kCore) + "int") ok = parse_integer(value).has_value();
    else if (tag == std::string(kCore) + "float") ok = parse_number(value).has_value();
    else if (tag == std::string(kCore) + "bool") ok = value == "true" || value == "false";
    else if (tag == std::string(kCore) + "null") ok = value.empty() || value == "~" || value == "null";
    else fail(mark, fmt::format("tag '{}' is not supported (plain YAML only; core tags !!str, !!int, !!float, "
                                "!!bool, !!null must match the value)", io::escape_control(tag)));
    if (!ok) fail(mark, fmt::format("'{}' is not a valid {}", io::escape_control(value), tag.substr(18)));
  }

  const std::string& file_;
  const Limits& limits_;
  int documents_ = 0;
  double total_ = 0;
  std::vector<Open> stack_;
  std::map<YAML::anchor_t, double> size_; // nodes of each anchored subtree, expanded
};

// Line and column of byte `offset` (1-based), for the UTF-8 message.
SourceLoc locate(const std::string& file, const std::string& text, std::size_t offset) {
  SourceLoc l{file, 1, 1};
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++l.line;
      l.column = 1;
    } else {
      ++l.column;
    }
  }
  return l;
}

} // namespace

std::string read_limited_file(const std::string& path, const Limits& limits, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScenarioError(SourceLoc{path, 0, 0}, fmt::format("cannot open the {}", what));
  std::string text;
  std::vector<char> chunk(1 << 16);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > limits.max_file_bytes) {
      throw ScenarioError(SourceLoc{path, 0, 0},
                          fmt::format("the {} is larger than {} bytes; raise the limit with --max-file-mb", what,
                                      limits.max_file_bytes));
    }
  }
  if (in.bad()) throw ScenarioError(SourceLoc{path, 0, 0}, fmt::format("cannot read the {}", what));
  return text;
}

YAML::Node load_yaml_safely(const std::string& text, const std::string& file, const Limits& limits) {
  if (text.size() > limits.max_file_bytes) {
    throw ScenarioError(SourceLoc{file, 0, 0}, fmt::format("larger than {} bytes; raise the limit with --max-file-mb",
                                                           limits.max_file_bytes));
  }
  if (const std::size_t bad = io::first_invalid_utf8(text); bad != std::string::npos) {
    throw ScenarioError(locate(file, text, bad), "not UTF-8 text (YAML files are UTF-8)");
  }
  try {
    std::istringstream in(text);
    YAML::Parser parser(in);
    Guard guard(file, limits);
    while (parser.HandleNextDocument(guard)) {
    }
    return YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    throw ScenarioError(at(file, e.mark), fmt::format("nesting depth exceeded ({})", e.msg));
  } catch (const YAML::Exception& e) {
    throw ScenarioError(at(file, e.mark), "YAML syntax: " + e.msg);
  }
}

} // namespace sreh::detail
