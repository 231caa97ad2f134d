/// @file
/// Everything of the geometry `geometry::s2`.
#pragma once

#include "s2/objects.hpp"
#include "s2/predicates.hpp"
#include "s2/constructions.hpp"
#include "s2/kernel.hpp"
