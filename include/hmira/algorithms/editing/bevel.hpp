// placeholder
#pragma once
#include "truncate.hpp"
