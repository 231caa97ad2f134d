/// @file
/// Everything of the geometry `geometry::e2`.
#pragma once

#include "e2/objects.hpp"
#include "e2/predicates.hpp"
#include "e2/constructions.hpp"
#include "e2/kernel.hpp"
