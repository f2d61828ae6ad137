#include "gait_test_util.h"
