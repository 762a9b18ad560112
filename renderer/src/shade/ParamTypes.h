// The one table of parameter types: how a plugin's declared type (RixSCType)
// is written in RIB, which RIB values may set it, and which outputs may feed it.
#pragma once

#include "RixShading.h"
#include "parse/ParamList.h"

namespace bxdflab {

/// The type as a RIB declaration writes it ("color", "float[2]"), or "invalid".
inline const char* ribTypeFor(RixSCType type) {
    switch (type) {
        case k_RixSCFloat: return "float";
        case k_RixSCInteger: return "int";
        case k_RixSCColor: return "color";
        case k_RixSCNormal: return "normal";
        case k_RixSCVector: return "vector";
        case k_RixSCPoint: return "point";
        case k_RixSCString: return "string";
        case k_RixSCFloat2: return "float[2]";
        default: return "invalid";
    }
}

/// The RIB type that declares a plugin's type (float[2] is two floats), for a
/// parameter the RIB wrote without one; Unknown for a type RIB cannot write.
inline ParamType paramTypeFor(RixSCType type) {
    switch (type) {
        case k_RixSCFloat:
        case k_RixSCFloat2: return ParamType::Float;
        case k_RixSCInteger: return ParamType::Int;
        case k_RixSCColor: return ParamType::Color;
        case k_RixSCNormal: return ParamType::Normal;
        case k_RixSCVector: return ParamType::Vector;
        case k_RixSCPoint: return ParamType::Point;
        case k_RixSCString: return ParamType::String;
        default: return ParamType::Unknown;
    }
}

/// The plugin type a RIB declaration gives (k_RixSCInvalidType for a type a
/// plugin cannot declare, or none).
inline RixSCType rixTypeFor(ParamType type) {
    switch (type) {
        case ParamType::Float: return k_RixSCFloat;
        case ParamType::Int: return k_RixSCInteger;
        case ParamType::Color: return k_RixSCColor;
        case ParamType::Point: return k_RixSCPoint;
        case ParamType::Vector: return k_RixSCVector;
        case ParamType::Normal: return k_RixSCNormal;
        case ParamType::String: return k_RixSCString;
        default: return k_RixSCInvalidType;
    }
}

/// How many numbers (or strings) one element of a parameter of this type holds.
inline int valuesPerElement(RixSCType type) {
    switch (type) {
        case k_RixSCFloat2: return 2;
        case k_RixSCColor:
        case k_RixSCNormal:
        case k_RixSCVector:
        case k_RixSCPoint: return 3;
        default: return 1;
    }
}

inline bool isGeometricType(RixSCType type) {
    return type == k_RixSCNormal || type == k_RixSCVector || type == k_RixSCPoint;
}

/// Whether a RIB value of type `given` can set a parameter declared `declared`
/// (an int sets a float; point, vector and normal set one another).
inline bool ribValueSets(RixSCType declared, ParamType given) {
    switch (declared) {
        case k_RixSCFloat: return given == ParamType::Float || given == ParamType::Int;
        case k_RixSCInteger: return given == ParamType::Int;
        case k_RixSCColor: return given == ParamType::Color;
        case k_RixSCNormal:
        case k_RixSCVector:
        case k_RixSCPoint: return given == ParamType::Vector || given == ParamType::Point || given == ParamType::Normal;
        case k_RixSCString: return given == ParamType::String;
        case k_RixSCFloat2: return given == ParamType::Float;
        default: return false;
    }
}

/// Whether an output of type `from` may feed an input of type `to`: the same
/// type, or two of the three-float types (colour, point, vector, normal), so
/// that an image can hold directions. A float never feeds a colour.
inline bool connectable(RixSCType from, RixSCType to) {
    auto triple = [](RixSCType t) { return t == k_RixSCColor || isGeometricType(t); };
    return from == to || (triple(from) && triple(to));
}

}  // namespace bxdflab
