#pragma once
#include "massprops/core/inertia.h"
