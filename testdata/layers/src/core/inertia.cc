// Fine: a core source includes its core header.
#include "massprops/core/inertia.h"
