/// @file
/// The generic BSP tree and all its algorithms: one include for the common jobs.
#pragma once

#include "boolean.hpp"
#include "depth_order.hpp"
#include "point_set.hpp"
#include "splitter.hpp"
#include "tree.hpp"
