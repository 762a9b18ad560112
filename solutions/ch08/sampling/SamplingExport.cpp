// Makes the sampling functions of Sampling.cpp callable by the course's
// checks (rixcheck, rixgrade), which load the exercise as the shared object
// sampling.so and call these two C functions. Keep this file as it is.
//   function 0: uniform hemisphere, 1: cosine hemisphere, 2: Phong lobe
#include "Sampling.h"

extern "C" PRMANEXPORT int RixSamplingExerciseSample(int function, float exponent, float xi0, float xi1, float* w,
                                                     float* pdf) {
    RtFloat2 const xi(xi0, xi1);
    RtVector3 d(0.0f, 0.0f, 0.0f);
    *pdf = 0.0f;
    switch (function) {
        case 0: d = sampling::sampleUniformHemisphere(xi, pdf); break;
        case 1: d = sampling::sampleCosineHemisphere(xi, pdf); break;
        case 2: d = sampling::samplePhongLobe(xi, exponent, pdf); break;
        default: return 1;
    }
    w[0] = d.x;
    w[1] = d.y;
    w[2] = d.z;
    return 0;
}

extern "C" PRMANEXPORT float RixSamplingExercisePdf(int function, float exponent, float const* w) {
    RtVector3 const d(w[0], w[1], w[2]);
    switch (function) {
        case 0: return sampling::uniformHemispherePdf(d);
        case 1: return sampling::cosineHemispherePdf(d);
        case 2: return sampling::phongLobePdf(d, exponent);
        default: return 0.0f;
    }
}
