// Text edits that turn a base filter description into a variant (docs/sweep.md "Variants"):
// ${name} placeholders and whole-setting replacement. The sweep only edits text; whether the
// result is a valid filter is the checker's call (the driver reports it with its own code).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace shadowc::sweep {

// The placeholder names in `text`, in order of first appearance.
std::vector<std::string> placeholders(const std::string& text);

// Replaces every ${name} with values.at(name). Throws std::out_of_range naming a missing one.
std::string fillPlaceholders(const std::string& text, const std::map<std::string, std::string>& values);

// Replaces the setting `keyword` (its line, and the lines its argument list continues on) with
// `keyword value`, or removes it when value is nullopt; adds it before the closing '}' when
// absent. `depth` and `moments` are one axis (docs/dsl.md), so setting one replaces the other.
std::string setSetting(const std::string& text, const std::string& keyword, const std::optional<std::string>& value);

}  // namespace shadowc::sweep
