/// @file
/// The number types, filtered predicates and the five geometries.
#pragma once

#include "number.hpp"
#include "filter.hpp"
#include "e1.hpp"
#include "e2.hpp"
#include "e3.hpp"
#include "s1.hpp"
#include "s2.hpp"
