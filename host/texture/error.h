#pragma once
// tf::Error: declared in the installed header, which the project includes like any user.
#include <texfilter/host.h>
