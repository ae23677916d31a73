#pragma once
// A core header that includes a check: the layering test must reject it.
#include "massprops/analysis/checks.h"
