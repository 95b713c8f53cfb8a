#include "harness.h"

const test_case suite_pia[] = {
    {0, 0}
};
