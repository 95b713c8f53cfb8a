#include "harness.h"

const test_case suite_harness[] = {
    {0, 0}
};
