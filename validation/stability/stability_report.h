// docs/stability.md as `shadowc stability --report` writes it: the results table plus one
// paragraph per failure mode with the fix we apply and the paper section it comes from. The
// paragraphs live here so that regenerating the document keeps them.
#pragma once

#include <string>
#include <vector>

#include "validation/stability/stability_suite.h"

namespace shadowc::validation {

std::string stabilityReport(const std::vector<CaseResult>& results);

}  // namespace shadowc::validation
