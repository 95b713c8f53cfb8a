#include "harness.h"

const test_case suite_loop[] = {
    {0, 0}
};
