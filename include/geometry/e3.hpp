/// @file
/// Everything of the geometry `geometry::e3`.
#pragma once

#include "e3/objects.hpp"
#include "e3/predicates.hpp"
#include "e3/constructions.hpp"
#include "e3/kernel.hpp"
