#include <doctest/doctest.h>

#include "kinematics/rotation.h"

TEST_CASE("placeholder") { CHECK(1 == 1); }
