#include "harness.h"

const test_case suite_trig[] = {
    {0, 0}
};
