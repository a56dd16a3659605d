// Today's date for the "measured on" of the project's reports and tables.
#pragma once

#include <ctime>
#include <string>

namespace whitted {

// YYYY-MM-DD, in UTC: the same on every machine of a run.
inline std::string todayUtc() {
    const std::time_t now = std::time(nullptr);
    char text[16];
    std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
    return text;
}

}  // namespace whitted
