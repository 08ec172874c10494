// FilterSpec <-> JSON (normalized spec, --print-spec, manifest "spec"). Filled by the front end.
#include "spec/filter_spec.h"
