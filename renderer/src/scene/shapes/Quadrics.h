// Every RenderMan quadric, for code that makes any of them.
#pragma once

#include "scene/shapes/Sphere.h"
#include "scene/shapes/Cylinder.h"
#include "scene/shapes/Disk.h"
#include "scene/shapes/Cone.h"
#include "scene/shapes/Paraboloid.h"
#include "scene/shapes/Hyperboloid.h"
