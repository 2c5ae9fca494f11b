// The limits a sizing checks, named in words for people (issue 37): the
// outputs for machines (--json, CSV) keep the tags.
#pragma once
#include <string>

namespace sreh::sizing {

// A limit's name in words ("torque_at_speed" -> "peak torque at speed");
// a tag it does not know comes back unchanged.
std::string limit_in_words(const std::string& limit);

} // namespace sreh::sizing
