// Twins for sizing runs. Building one compiles MJCF (mj_loadXML), which is
// serialised here so that sweep threads may build twins concurrently; the
// runs themselves are independent (each thread its own Twin).
#pragma once
#include <memory>

#include "twin/twin.hpp"

namespace sreh::sizing {

// Throws SizingInputError for a load the twin refuses (e.g. above
// 15000 g cm^2, manual 6.2 index 64.4).
std::unique_ptr<Twin> make_twin(const TwinConfig& config);

struct KeptTwin;

// A twin lent for one run; back to the pool when this goes.
class PooledTwin {
 public:
  explicit PooledTwin(std::unique_ptr<KeptTwin> kept);
  PooledTwin(PooledTwin&&) noexcept;
  PooledTwin& operator=(PooledTwin&&) = delete;
  ~PooledTwin();
  Twin& operator*() const;

 private:
  std::unique_ptr<KeptTwin> kept_;
};

// A twin exactly as make_twin(config) builds it, for one run (issue 31): the
// process keeps the last few twins returned, each with a snapshot taken
// right after construction, and lends one of the same world restored to
// that snapshot (Twin::restore continues bit for bit, A-TWIN-34): ~5 us
// instead of ~1 ms for a construction. The pool is shared by all threads
// (issue 37). Configs with a trace or move sink or a memory image are not
// kept (sizing uses none): std::logic_error.
PooledTwin fresh_twin(const TwinConfig& config);

} // namespace sreh::sizing
