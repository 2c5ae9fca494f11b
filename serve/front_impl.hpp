// The members of serve/front.hpp's Front, for the three fronts' .cpp files
// only (after their Impl, before `template class Front<...>;`).
#pragma once
#include "serve/front.hpp"

namespace sreh::serve {

template <class O>
Front<O>::Front(Hub& hub, const O& options) : impl_(std::make_unique<Impl>(hub, options)) {}
template <class O>
Front<O>::~Front() { stop(); }
template <class O>
int Front<O>::bound_port() const { return impl_->port(); }
template <class O>
void Front<O>::start() { impl_->start(); }
template <class O>
void Front<O>::stop() { impl_->stop(); }

} // namespace sreh::serve
