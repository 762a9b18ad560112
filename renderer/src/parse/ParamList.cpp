#include "parse/ParamList.h"

#include <algorithm>
#include <sstream>

#include "core/Spelling.h"
#include "parse/StandardDeclarations.h"

namespace bxdflab {

int componentsOf(ParamType type) {
    switch (type) {
        case ParamType::Color:
        case ParamType::Point:
        case ParamType::Vector:
        case ParamType::Normal: return 3;
        case ParamType::HPoint: return 4;
        case ParamType::Matrix: return 16;
        default: return 1;
    }
}

const char* paramTypeName(ParamType type) {
    switch (type) {
        case ParamType::Float: return "float";
        case ParamType::Int: return "int";
        case ParamType::Color: return "color";
        case ParamType::Point: return "point";
        case ParamType::Vector: return "vector";
        case ParamType::Normal: return "normal";
        case ParamType::HPoint: return "hpoint";
        case ParamType::String: return "string";
        case ParamType::Matrix: return "matrix";
        case ParamType::Unknown: return "untyped";
    }
    return "?";
}

Vec3 ColorSamples::rgb(float const* numbers) const {
    if (toRGB.empty()) return Vec3(numbers[0], numbers[1], numbers[2]);
    Vec3 out(0.0f);
    for (size_t i = 0; i < count; ++i)
        out += numbers[i] * Vec3(toRGB[3 * i], toRGB[3 * i + 1], toRGB[3 * i + 2]);
    return out;
}

Declarations::Declarations() {
    for (auto const& [name, declaration] : standardDeclarations()) {
        ParamDecl decl;
        std::string error;
        parseDeclaration(std::string(declaration) + " " + name, decl, error);
        decl.standard = true;
        m_known[name] = decl;
    }
}

bool Declarations::parseDeclaration(std::string const& text, ParamDecl& out, std::string& error) {
    std::istringstream words(text);
    std::vector<std::string> parts;
    for (std::string w; words >> w;) parts.push_back(w);
    if (parts.empty()) {
        error = "empty parameter name";
        return false;
    }
    out = ParamDecl();
    out.name = parts.back();
    parts.pop_back();
    size_t i = 0;
    if (i < parts.size() && parts[i] == "reference") {
        out.reference = true;
        ++i;
    }
    static const char* classes[] = {"constant", "uniform", "varying", "vertex", "facevarying", "facevertex"};
    if (i < parts.size())
        for (const char* cls : classes)
            if (parts[i] == cls) {
                out.storageClass = parts[i++];
                break;
            }
    if (i >= parts.size()) {
        if (!parts.empty() || !out.storageClass.empty() || out.reference) {
            error = "declaration '" + text + "' has a storage class but no type";
            return false;
        }
        error = "";  // a bare name: caller looks it up
        return false;
    }
    std::string type = parts[i++];
    size_t bracket = type.find('[');
    if (bracket != std::string::npos) {
        size_t close = type.find(']', bracket);
        if (close == std::string::npos) {
            error = "unbalanced '[' in type '" + type + "'";
            return false;
        }
        try {
            out.arraySize = std::stoi(type.substr(bracket + 1, close - bracket - 1));
        } catch (...) {
            error = "bad array length in type '" + type + "'";
            return false;
        }
        // 0 is an empty array: RenderMan for Maya writes PxrSurface's unused "int[0] utilityPattern" [].
        if (out.arraySize < 0) {
            error = "array length must not be negative in '" + type + "'";
            return false;
        }
        type = type.substr(0, bracket);
    }
    static const std::map<std::string, ParamType> types = {
        {"float", ParamType::Float},   {"int", ParamType::Int},       {"integer", ParamType::Int},
        {"color", ParamType::Color},   {"point", ParamType::Point},   {"vector", ParamType::Vector},
        {"normal", ParamType::Normal}, {"hpoint", ParamType::HPoint}, {"string", ParamType::String},
        {"matrix", ParamType::Matrix}, {"bool", ParamType::Int},
        // PRMan's Blobby reference positions: a matrix per primitive.
        {"mpoint", ParamType::Matrix},
        // RenderMan's structs (layered materials) are passed whole to plugins this renderer does not have.
        {"struct", ParamType::Unknown},
        // Filters naming other filters by handle (PxrSampleFilterCombiner's "reference samplefilter[2] filter").
        {"samplefilter", ParamType::Unknown}, {"displayfilter", ParamType::Unknown}, {"lightfilter", ParamType::Unknown},
    };
    auto found = types.find(type);
    if (found == types.end()) {
        error = "unknown parameter type '" + type + "' (expected float, int, color, point, vector, normal, hpoint, matrix, string)";
        return false;
    }
    out.type = found->second;
    if (i != parts.size()) {
        error = "cannot parse declaration '" + text + "'";
        return false;
    }
    return true;
}

void Declarations::declare(std::string const& name, std::string const& declaration, SourceLocation const& where) {
    ParamDecl decl;
    std::string error;
    if (!parseDeclaration(declaration + " " + name, decl, error))
        throw RibError(where, "Declare \"" + name + "\": " + (error.empty() ? "missing type" : error));
    m_known[name] = decl;
}

ParamDecl Declarations::resolve(std::string const& token, SourceLocation const& where) const {
    ParamDecl decl;
    std::string error;
    if (parseDeclaration(token, decl, error)) return decl;
    if (!error.empty()) throw RibError(where, error);
    auto found = m_known.find(token);
    if (found != m_known.end()) return found->second;
    ParamDecl untyped;
    untyped.name = token;
    untyped.type = ParamType::Unknown;
    untyped.untyped = true;
    return untyped;
}

size_t Param::count() const {
    if (decl.type == ParamType::String) return strings.size();
    if (decl.type == ParamType::Int) return ints.size();
    return floats.size() / static_cast<size_t>(componentsOf(decl.type));
}

std::optional<std::string> Param::firstValueText() const {
    if (!strings.empty()) return strings.front();
    if (floats.empty()) return std::nullopt;
    std::ostringstream number;
    number << floats.front();
    return number.str();
}

namespace {

/// A parameter the renderer makes itself (no source location): its name and type, values to come.
Param madeParam(std::string const& name, ParamType type) {
    Param p;
    p.decl.name = name;
    p.decl.type = type;
    return p;
}

}  // namespace

Param colorParam(std::string const& name, Vec3 const& value) {
    Param p = madeParam(name, ParamType::Color);
    p.floats = {value.x, value.y, value.z};
    return p;
}

Param floatParam(std::string const& name, float value) {
    Param p = madeParam(name, ParamType::Float);
    p.floats = {value};
    return p;
}

Param intParam(std::string const& name, int value) {
    Param p = madeParam(name, ParamType::Int);
    p.ints = {value};
    p.floats = {static_cast<float>(value)};  // as a parsed int has them
    return p;
}

Param stringParam(std::string const& name, std::string const& value) {
    Param p = madeParam(name, ParamType::String);
    p.strings = {value};
    return p;
}

bool giveType(Param& param, ParamType type, int arraySize) {
    if (!param.decl.untyped || param.decl.reference || type == ParamType::Unknown) return false;
    Param typed = param;
    typed.decl.type = type;
    typed.decl.arraySize = arraySize;
    typed.decl.untyped = false;
    if (type == ParamType::String) {
        if (param.strings.empty() || !param.floats.empty()) return false;
    } else {
        size_t const group = static_cast<size_t>(componentsOf(type) * arraySize);
        if (!param.strings.empty() || param.floats.empty() || param.floats.size() % group != 0) return false;
        for (float f : param.floats) {
            if (!std::isfinite(f) || (type == ParamType::Int && !isWholeInt(f))) return false;
            if (type == ParamType::Int) typed.ints.push_back(static_cast<int>(f));
        }
    }
    param = std::move(typed);
    return true;
}

void ParamList::typeUntyped(std::map<std::string, ParamType> const& declared, std::string const& owner) {
    for (Param& p : m_params) {
        auto found = declared.find(p.name());
        if (!p.decl.untyped || p.decl.reference || found == declared.end()) continue;
        if (!giveType(p, found->second))
            throw RibError(p.location, owner + ": parameter \"" + p.name() + "\" is a " + paramTypeName(found->second) +
                                           ", and its value cannot be one (write \"" + paramTypeName(found->second) +
                                           " " + p.name() + "\")");
    }
}

void ParamList::add(Param param) {
    for (auto& existing : m_params)
        if (existing.name() == param.name()) {
            existing = std::move(param);
            return;
        }
    m_params.push_back(std::move(param));
}

Param const* ParamList::find(std::string const& name) const {
    for (auto const& p : m_params)
        if (p.name() == name) return &p;
    return nullptr;
}

Param const* ParamList::take(std::string const& name) const {
    Param const* p = find(name);
    if (!p) {
        noteAbsent(name);
        return nullptr;
    }
    p->used = true;
    if (p->decl.untyped)
        throw RibError(p->location, "parameter \"" + name + "\" has no type: write it as \"<type> " + name +
                                        "\", e.g. \"float " + name + "\", or declare it with Declare");
    return p;
}

void ParamList::ignore(std::string const& name) const {
    if (Param const* p = find(name)) p->used = true;
}

void ParamList::noteAbsent(std::string const& name) const {
    if (std::find(m_absentAskedFor.begin(), m_absentAskedFor.end(), name) == m_absentAskedFor.end())
        m_absentAskedFor.push_back(name);
}

Param const& ParamList::expect(Param const& p, std::initializer_list<ParamType> types, size_t count) const {
    bool typeOk = false;
    std::string wanted;
    for (ParamType t : types) {
        typeOk = typeOk || p.decl.type == t;
        wanted += (wanted.empty() ? "" : " or ") + std::string(paramTypeName(t));
    }
    if (!typeOk)
        throw RibError(p.location, "parameter \"" + p.name() + "\" should be " + wanted + ", not " +
                                       paramTypeName(p.decl.type));
    if (count && p.count() != count)
        throw RibError(p.location, "parameter \"" + p.name() + "\" needs " + std::to_string(count) + " value" +
                                       (count > 1 ? "s" : "") + ", got " + std::to_string(p.count()));
    return p;
}

float ParamList::getFloat(std::string const& name, float dflt) const {
    Param const* p = take(name);
    if (!p) return dflt;
    expect(*p, {ParamType::Float, ParamType::Int}, 1);
    return p->floats[0];
}

int ParamList::getInt(std::string const& name, int dflt) const {
    Param const* p = take(name);
    if (!p) return dflt;
    expect(*p, {ParamType::Int, ParamType::Float}, 1);
    if (p->decl.type == ParamType::Int) return p->ints[0];
    float v = p->floats[0];
    if (!isWholeInt(v))
        throw RibError(p->location, "parameter \"" + name + "\" must be a whole number that fits an int, got " + std::to_string(v));
    return static_cast<int>(v);
}

Vec3 ParamList::getColor(std::string const& name, Vec3 const& dflt) const {
    Param const* p = take(name);
    if (!p) return dflt;
    expect(*p, {ParamType::Color}, 1);
    return Vec3(p->floats[0], p->floats[1], p->floats[2]);
}

Vec3 ParamList::getVector(std::string const& name, Vec3 const& dflt) const {
    Param const* p = take(name);
    if (!p) return dflt;
    expect(*p, {ParamType::Vector, ParamType::Point, ParamType::Normal}, 1);
    return Vec3(p->floats[0], p->floats[1], p->floats[2]);
}

std::string ParamList::getString(std::string const& name, std::string const& dflt) const {
    Param const* p = take(name);
    if (!p) return dflt;
    expect(*p, {ParamType::String}, 1);
    return p->strings[0];
}

std::vector<float> const* ParamList::getFloats(std::string const& name, ParamType type) const {
    Param const* p = take(name);
    if (!p) return nullptr;
    if (type == ParamType::Float)
        expect(*p, {ParamType::Float, ParamType::Int}, 0);
    else
        expect(*p, {type}, 0);
    return &p->floats;
}

std::vector<float> const* ParamList::getNormals(std::string const& name) const {
    Param const* p = find(name);
    if (!p || p->decl.reference) return nullptr;
    return getFloats(name, p->decl.type == ParamType::Vector ? ParamType::Vector : ParamType::Normal);
}

std::vector<int> const* ParamList::getInts(std::string const& name) const {
    Param const* p = take(name);
    if (!p) return nullptr;
    expect(*p, {ParamType::Int, ParamType::Float}, 0);
    return &p->ints;
}

void ParamList::warnUnused(Diagnostics& diagnostics, std::string const& owner,
                           std::function<bool(std::string const& name)> const& firstTime) const {
    for (auto const& p : m_params) {
        if (p.used || isRendererMetadata(p.name())) continue;
        if (firstTime && !firstTime(p.name())) continue;
        if (p.decl.untyped)
            diagnostics.warn(p.location, owner + ": parameter \"" + p.name() +
                                             "\" has no type and is not a standard name; ignored");
        else {
            std::string const meant = closestSpelling(p.name(), m_absentAskedFor);
            diagnostics.warn(p.location, owner + ": parameter \"" + p.name() + "\" is not used; ignored" +
                                             (meant.empty() ? "" : " (did you mean \"" + meant + "\"?)"));
        }
    }
}

}  // namespace bxdflab
