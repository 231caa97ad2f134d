/// @file
/// Everything of the geometry `geometry::e1`.
#pragma once

#include "e1/objects.hpp"
#include "e1/predicates.hpp"
#include "e1/constructions.hpp"
#include "e1/kernel.hpp"
