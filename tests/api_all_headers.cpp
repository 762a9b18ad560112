// Every header of the Rix API, for the test that compiles them as C++14 with
// all warnings as errors (the course text builds its plugins with -std=c++14).
#include "RiTypesHelper.h"
#include "RixBxdf.h"
#include "RixBxdfLobe.h"
#include "RixBxdfScratch.h"
#include "RixIntegrator.h"
#include "RixInterfaces.h"
#include "RixPattern.h"
#include "RixPredefinedStrings.hpp"
#include "RixRNG.h"
#include "RixShading.h"
#include "RixShadingUtils.h"
#include "bxdf/PxrSurfaceOpacity.h"

int main() { return 0; }
