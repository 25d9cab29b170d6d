// gnuplot-iostream, included as a system header so that our warning flags stay quiet about it.
#pragma once
#pragma GCC system_header

#include <gnuplot-iostream.h>
