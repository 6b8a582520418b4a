#include <doctest/doctest.h>

#include "motion/integrator.h"

TEST_CASE("placeholder") { CHECK(1 == 1); }
