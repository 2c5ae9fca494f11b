// The bearer check of the HTTP front: "Authorization: Bearer <token>", the
// scheme case-insensitive (RFC 7235 2.1), the token compared in constant time.
#pragma once
#include <string>

namespace sreh::serve {

bool bearer_matches(const std::string& authorization, const std::string& token);

} // namespace sreh::serve
