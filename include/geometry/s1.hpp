/// @file
/// Everything of the geometry `geometry::s1`.
#pragma once

#include "s1/objects.hpp"
#include "s1/predicates.hpp"
#include "s1/constructions.hpp"
#include "s1/kernel.hpp"
