#include "scenarios/result_json_stream.hpp"

#include <map>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "io/spool.hpp"
#include "scenarios/result_json.hpp"

namespace sreh {
namespace {

// As the CLI prints it: names and texts come from the file, invalid UTF-8 is
// replaced, never an internal error.
std::string dump(const nlohmann::json& j) { return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace); }

// nlohmann's pretty printer indents a value nested `depth` levels deep by
// 2 * depth more spaces on every line after its first. A raw newline never
// occurs inside a dumped string (it is escaped), so every '\n' is one of
// the printer's own line breaks.
void write_indented(std::ostream& out, const std::string& text, int depth) {
  const std::string pad(static_cast<std::size_t>(2 * depth), ' ');
  std::size_t from = 0;
  for (std::size_t nl = text.find('\n'); nl != std::string::npos; nl = text.find('\n', from)) {
    out.write(text.data() + from, static_cast<std::streamsize>(nl + 1 - from));
    out << pad;
    from = nl + 1;
  }
  out.write(text.data() + from, static_cast<std::streamsize>(text.size() - from));
}

// One array member of the top-level object, elements appended as they come.
// Pretty-printed, an array at depth 1 is "[\n    e1,\n    e2\n  ]", or "[]".
class ArraySpool {
 public:
  void add(const nlohmann::json& element) {
    std::ostream& out = spool_.stream();
    out << (count_++ == 0 ? "\n    " : ",\n    ");
    write_indented(out, dump(element), 2);
  }
  void write(std::ostream& out) {
    out << '[';
    if (count_ == 0) {
      out << ']';
      return;
    }
    spool_.copy_to(out);
    out << "\n  ]";
  }

 private:
  io::Spool spool_;
  unsigned long long count_ = 0;
};

} // namespace

struct ResultJsonStream::Impl {
  // Keyed by the member names to_json gives these arrays.
  std::map<std::string, ArraySpool> arrays;
  ArraySpool& checks = arrays["checks"];
  ArraySpool& failures = arrays["failures"];
  ArraySpool& moves = arrays["moves"];
};

ResultJsonStream::ResultJsonStream() : impl_(std::make_unique<Impl>()) {}
ResultJsonStream::~ResultJsonStream() = default;

void ResultJsonStream::attach(RunOptions& options) {
  Impl& s = *impl_;
  options.check_sink = [&s](const CheckRecord& c) { s.checks.add(check_json(c)); };
  options.failure_sink = [&s](const std::string& f) { s.failures.add(nlohmann::json(f)); };
  options.move_sink = [&s](const MoveRecord& m) { s.moves.add(move_json(m)); };
}

void ResultJsonStream::write(std::ostream& out, const RunResult& result) {
  // Everything but the streamed arrays comes from to_json, so the members,
  // their order (sorted, nlohmann::json's object) and their values are its own.
  const nlohmann::json head = to_json(result);
  out << '{';
  bool first = true;
  for (const auto& [key, value] : head.items()) {
    out << (first ? "\n  " : ",\n  ") << dump(nlohmann::json(key)) << ": ";
    first = false;
    if (auto a = impl_->arrays.find(key); a != impl_->arrays.end()) {
      a->second.write(out);
    } else {
      write_indented(out, dump(value), 1);
    }
  }
  out << (first ? "}" : "\n}");
}

} // namespace sreh
