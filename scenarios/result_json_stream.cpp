#include "scenarios/result_json_stream.hpp"

#include <map>
#include <ostream>
#include <string>

#include "io/spool.hpp"
#include "scenarios/result_json.hpp"

namespace sreh {
namespace {

// As the CLI prints it: names and texts come from the file, invalid UTF-8 is
// replaced, never an internal error.
std::string dump(const nlohmann::json& j, int indent) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

// nlohmann's pretty printer indents a value nested `depth` levels deep by
// 2 * depth more spaces on every line after its first. A raw newline never
// occurs inside a dumped string (it is escaped), so every '\n' is one of
// the printer's own line breaks.
void write_indented(std::ostream& out, const std::string& text, const std::string& pad) {
  std::size_t from = 0;
  for (std::size_t nl = text.find('\n'); nl != std::string::npos; nl = text.find('\n', from)) {
    out.write(text.data() + from, static_cast<std::streamsize>(nl + 1 - from));
    out << pad;
    from = nl + 1;
  }
  out.write(text.data() + from, static_cast<std::streamsize>(text.size() - from));
}

// The printer's layout of the top-level object (depth 0) and of its array
// members (depth 1): pretty "{\n  "k": [\n    e1,\n    e2\n  ]\n}",
// compact {"k":[e1,e2]}; empty "[]" and "{}" in both.
// (Written piece by piece: GCC 12 warns wrongly on string concatenation here.)
struct Layout {
  int indent;
  bool pretty() const { return indent >= 0; }
  std::string pad(int depth) const { return std::string(pretty() ? static_cast<std::size_t>(indent * depth) : 0u, ' '); }
  void open(std::ostream& out, bool first, int depth) const {
    if (!first) out << ',';
    if (pretty()) out << '\n' << pad(depth);
  }
  void close(std::ostream& out, int depth) const {
    if (pretty()) out << '\n' << pad(depth);
  }
  const char* colon() const { return pretty() ? ": " : ":"; }
  void value(std::ostream& out, const nlohmann::json& j, int depth) const {
    write_indented(out, dump(j, indent), pad(depth));
  }
};

// One array member of the top-level object, elements appended as they come.
class ArraySpool {
 public:
  void add(const Layout& layout, const nlohmann::json& element) {
    std::ostream& out = spool_.stream();
    layout.open(out, count_++ == 0, 2);
    layout.value(out, element, 2);
  }
  void write(std::ostream& out, const Layout& layout) {
    out << '[';
    if (count_ > 0) {
      spool_.copy_to(out);
      layout.close(out, 1);
    }
    out << ']';
  }

 private:
  io::Spool spool_;
  unsigned long long count_ = 0;
};

} // namespace

struct ResultJsonStream::Impl {
  explicit Impl(int indent) : layout{indent < 0 ? -1 : indent} {}
  Layout layout;
  // Keyed by the member names to_json gives these arrays.
  std::map<std::string, ArraySpool> arrays;
  ArraySpool& checks = arrays["checks"];
  ArraySpool& failures = arrays["failures"];
  ArraySpool& moves = arrays["moves"];
};

ResultJsonStream::ResultJsonStream(int indent) : impl_(std::make_unique<Impl>(indent)) {}
ResultJsonStream::~ResultJsonStream() = default;

void ResultJsonStream::attach(RunOptions& options) {
  Impl& s = *impl_;
  options.check_sink = [&s](const CheckRecord& c) { s.checks.add(s.layout, check_json(c)); };
  options.failure_sink = [&s](const std::string& f) { s.failures.add(s.layout, nlohmann::json(f)); };
  options.move_sink = [&s](const MoveRecord& m) { s.moves.add(s.layout, move_json(m)); };
}

void ResultJsonStream::write(std::ostream& out, const RunResult& result, const nlohmann::json& extra) {
  // Everything but the streamed arrays comes from to_json, so the members,
  // their order (sorted, nlohmann::json's object) and their values are its own.
  nlohmann::json head = to_json(result);
  head.update(extra);
  const Layout& layout = impl_->layout;
  out << '{';
  bool first = true;
  for (const auto& [key, value] : head.items()) {
    layout.open(out, first, 1);
    out << dump(nlohmann::json(key), -1) << layout.colon();
    first = false;
    if (auto a = impl_->arrays.find(key); a != impl_->arrays.end()) {
      a->second.write(out, layout);
    } else {
      layout.value(out, value, 1);
    }
  }
  if (!first) layout.close(out, 0);
  out << '}';
}

} // namespace sreh
