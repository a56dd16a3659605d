// printf's formatting into a std::string: the figures in a report or a
// plan's reasons. GCC checks each call's arguments against its pattern.
#pragma once

#include <string>

namespace whitted {

std::string printed(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

}  // namespace whitted
