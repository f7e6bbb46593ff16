#pragma once
// B-rep fixtures built with OpenCASCADE primitives, handed to the module as BREP strings (the
// path FreeCAD uses), and the paths of the sample and bad-input files.
#include <string>

#include "framefix/brep/brep_model.h"

namespace framefix::test {

std::string sample(const std::string& name);   // samples/<name>.step
std::string bad_input(const std::string& name);  // tests/data/<name>

BrepModel box(double x, double y, double z);
// Box [0,1]^3 with a blind cylindrical hole (radius 0.25, depth 0.5) from the top face.
BrepModel box_with_blind_hole();
// Box [0,1]^3 with the vertical edge at x = y = 0 rounded (radius 0.2).
BrepModel box_with_fillet();

}  // namespace framefix::test
