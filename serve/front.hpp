// One network front of the virtual master (Modbus TCP, HTTP/JSON, MQTT),
// declared once for all three: constructed bound (or connected) to its
// address, throwing std::runtime_error naming it; serving from start()
// until stop() (also on destruction). Each front's .cpp defines
// Front<ItsOptions>::Impl with start(), stop() and port(), includes
// serve/front_impl.hpp and instantiates the class.
#pragma once
#include <memory>

#include "serve/hub.hpp"

namespace sreh::serve {

template <class Options>
class Front {
 public:
  Front(Hub& hub, const Options& options);
  ~Front();
  Front(const Front&) = delete;
  Front& operator=(const Front&) = delete;
  int bound_port() const; // where it listens (options' port 0: the OS picked it); 0 for a client (MQTT)
  void start();
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// In a front's header, after its `using`: the members are instantiated in the
// front's .cpp only (after its Impl), so no other file instantiates them, also
// where serve/front_impl.hpp is visible without that Impl (a unity build puts
// several .cpp files in one translation unit). Not `extern template class`:
// clang refuses the .cpp's Impl after it.
#define SREH_SERVE_EXTERN_FRONT(Options)                         \
  extern template Front<Options>::Front(Hub&, const Options&); \
  extern template Front<Options>::~Front();                    \
  extern template int Front<Options>::bound_port() const;      \
  extern template void Front<Options>::start();                \
  extern template void Front<Options>::stop()

} // namespace sreh::serve
