#include "harness.h"

const test_case suite_real[] = {
    {0, 0}
};
