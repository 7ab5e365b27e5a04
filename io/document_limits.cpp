// Limits on a YAML document (io/document_limits.hpp): one pass over the parser's events, which
// never builds or expands anything, so its time is linear in the text whatever the text holds.
#include "io/document_limits.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <yaml-cpp/eventhandler.h>

namespace chaser::io {
namespace {

struct StopScan {};  // thrown by the scanner at the node limit; nothing past it is read

std::string shortened(std::string_view text) {
  if (text.size() <= 40) return std::string(text);
  return std::string(text.substr(0, 37)) + "...";
}

// The first place a problem was seen, and how often it was seen.
struct Occurrence {
  std::size_t count = 0;
  std::string path;
  int line = 0;
  std::string detail;
};

class LimitScanner : public YAML::EventHandler {
 public:
  explicit LimitScanner(std::string prefix) : prefix_(std::move(prefix)) {}

  // A scenario is one document. yaml-cpp 0.7 reads a text holding only "," as an endless stream of
  // empty documents, so the scan stops at the second.
  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ == 1) return;
    second_document_ = mark;
    throw StopScan{};
  }
  void OnDocumentEnd() override {}
  void OnAnchor(const YAML::Mark&, const std::string& name) override { anchor_names_.push_back(name); }
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    node(mark, anchor);
    advance("");
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    node(mark, 0);
    note(aliases_, mark, fmt::format("'*{}'", anchor_name(anchor)));
    advance("");
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                const std::string& value) override {
    node(mark, anchor);
    if (value.size() > kMaxScalarBytes) note(long_scalars_, mark, fmt::format("{} bytes", value.size()));
    advance(value);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, anchor, false);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, anchor, true);
  }
  void OnMapEnd() override { close(); }

  // Reports what was found; true if nothing was.
  bool report(const std::string& source, Diagnostics& diag) const {
    const std::size_t before = diag.errors().size();
    if (documents_ > 1)
      diag.add(source, fmt::format("must hold exactly one YAML document (a second begins at line {}, column {})",
                                   second_document_.line + 1, second_document_.column + 1));
    if (too_many_nodes_.count)
      diag.add(source, fmt::format("has more than {} nodes (keys, values and list items; the limit was passed at "
                                   "line {}): the shipped scenarios have under a thousand", kMaxDocumentNodes, too_many_nodes_.line));
    add(diag, anchors_, "anchors are not allowed: write the value out in full (docs/scenario.md, \"Limits\")");
    add(diag, aliases_, "aliases are not allowed: write the value out in full (docs/scenario.md, \"Limits\")");
    add(diag, too_deep_, fmt::format("lists and mappings may nest at most {} deep", kMaxNestingDepth));
    add(diag, long_scalars_, fmt::format("a key or value may be at most {} bytes long", kMaxScalarBytes));
    return diag.errors().size() == before;
  }

 private:
  struct Frame {
    bool map;
    bool at_key = true;     // mapping: the next node is a key
    std::size_t index = 0;  // list: the next item's index
    std::string key;        // mapping: the key of the value being read
  };

  static void add(Diagnostics& diag, const Occurrence& o, const std::string& rule) {
    if (o.count == 0) return;
    diag.add(o.path, fmt::format("{} (got {} at line {}{})", rule, o.detail, o.line,
                                 o.count > 1 ? fmt::format("; {} in the text", o.count) : ""));
  }

  std::string anchor_name(YAML::anchor_t anchor) const {
    return anchor >= 1 && anchor <= anchor_names_.size() ? shortened(anchor_names_[anchor - 1]) : "?";
  }

  // The key path of the node being read now: a mapping's key is reported at the mapping.
  std::string path() const {
    std::string out = prefix_;
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (!f.map) out = join_path(out, std::to_string(f.index));
      else if (!f.at_key) out = join_path(out, f.key);
      else if (i + 1 < frames_.size()) out = join_path(out, "(key)");
    }
    return out;
  }

  void note(Occurrence& o, const YAML::Mark& mark, std::string detail) {
    if (o.count++ > 0) return;
    o.path = path();
    o.line = mark.line + 1;
    o.detail = std::move(detail);
  }

  void node(const YAML::Mark& mark, YAML::anchor_t anchor) {
    if (++nodes_ > kMaxDocumentNodes) {
      note(too_many_nodes_, mark, "");
      throw StopScan{};
    }
    if (anchor != 0) note(anchors_, mark, fmt::format("'&{}'", anchor_name(anchor)));
  }

  void open(const YAML::Mark& mark, YAML::anchor_t anchor, bool map) {
    node(mark, anchor);
    if (static_cast<int>(frames_.size()) >= kMaxNestingDepth)
      note(too_deep_, mark, fmt::format("a {} at depth {}", map ? "mapping" : "list", frames_.size() + 1));
    frames_.push_back(Frame{.map = map, .at_key = true, .index = 0, .key = {}});
  }

  void close() {
    if (frames_.empty()) return;
    frames_.pop_back();
    advance("(key)");
  }

  // A node of the innermost collection is complete; `text` is its scalar text, for a key.
  void advance(std::string_view text) {
    if (frames_.empty()) return;
    Frame& f = frames_.back();
    if (!f.map) {
      ++f.index;
    } else if (f.at_key) {
      f.key = shortened(text.empty() ? "(key)" : text);
      f.at_key = false;
    } else {
      f.at_key = true;
    }
  }

  std::string prefix_;
  std::vector<Frame> frames_;
  std::vector<std::string> anchor_names_;
  std::size_t nodes_ = 0;
  std::size_t documents_ = 0;
  YAML::Mark second_document_;
  Occurrence too_many_nodes_, anchors_, aliases_, too_deep_, long_scalars_;
};

struct TreeWalk {
  std::size_t nodes = 0;
  int deepest = 0;  // lists and mappings inside each other, as LimitScanner counts them

  // `depth`: the collections around `node`. Stops descending past the depth limit and counting
  // past the node limit.
  void visit(const YAML::Node& node, int depth) {
    if (++nodes > kMaxDocumentNodes || !(node.IsMap() || node.IsSequence())) return;
    deepest = std::max(deepest, depth + 1);
    if (depth + 1 > kMaxNestingDepth) return;
    for (const auto& item : node) {
      if (nodes > kMaxDocumentNodes) return;
      if (node.IsMap()) {
        visit(item.first, depth + 1);
        visit(item.second, depth + 1);
      } else {
        visit(item, depth + 1);
      }
    }
  }
};

}  // namespace

bool check_yaml_text(std::string_view text, const std::string& source, const std::string& path_prefix,
                     Diagnostics& diag) {
  if (text.size() > kMaxDocumentBytes) {
    diag.add(source, fmt::format("is longer than {} bytes (1 MiB), the most a scenario may hold "
                                 "(msr_terminal.yaml: 11 KB)", kMaxDocumentBytes));
    return false;
  }
  LimitScanner scanner(path_prefix);
  std::istringstream stream{std::string(text)};
  try {
    YAML::Parser parser(stream);
    while (parser.HandleNextDocument(scanner)) {
    }
  } catch (const StopScan&) {
  } catch (const YAML::Exception&) {
    // Invalid YAML: the caller's parser reports it in its own words. Everything before the error
    // was scanned, and the caller's parser stops at the same place.
  }
  return scanner.report(source, diag);
}

bool check_document_tree(const YAML::Node& root, const std::string& source, Diagnostics& diag) {
  TreeWalk walk;
  walk.visit(root, 0);
  bool ok = true;
  if (walk.nodes > kMaxDocumentNodes) {
    diag.add(source, fmt::format("has more than {} nodes after the --set overrides (keys, values and list items)",
                                 kMaxDocumentNodes));
    ok = false;
  }
  if (walk.deepest > kMaxNestingDepth) {
    diag.add(source, fmt::format("nests lists and mappings more than {} deep after the --set overrides",
                                 kMaxNestingDepth));
    ok = false;
  }
  return ok;
}

}  // namespace chaser::io
