#include "massprops/model.h"
