#pragma once
// MIP chains (floor rule, linear light): declared in the installed header (texfilter::host).
#include <texfilter/host.h>
