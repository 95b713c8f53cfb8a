#include "harness.h"

const test_case suite_loop_limit[] = {
    {0, 0}
};
