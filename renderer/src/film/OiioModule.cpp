// The OpenImageIO image files as a loadable module: rixrender opens it the
// first time a scene reads or writes an image, so a render that only reports
// its pixels over a descriptor (the grader's), or --help, never maps
// OpenImageIO's few hundred shared libraries.
#include "film/OiioImageFiles.h"

extern "C" __attribute__((visibility("default"))) bxdflab::ImageFiles const* bxdflabOpenImageFiles() {
    return &bxdflab::openImageIOFiles();
}
