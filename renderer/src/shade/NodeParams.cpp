#include "shade/NodeParams.h"

#include <cmath>

#include "core/Spelling.h"
#include "shade/PatternInstance.h"

namespace bxdflab {
namespace {

std::vector<std::string> namesIn(ShadingPlugin const& plugin, bool outputs) {
    std::vector<std::string> names;
    for (size_t i = 0; i < plugin.paramTable().size(); ++i)
        if ((plugin.paramTable()[i].access == k_RixSCOutput) == outputs && !plugin.paramNames()[i].empty())
            names.push_back(plugin.paramNames()[i]);
    return names;
}

/// What to say about a name a plugin does not have among its inputs (or
/// outputs): the one it was likely meant to be, then all of them.
std::string namesHint(std::string const& name, ShadingPlugin const& plugin, bool outputs) {
    std::vector<std::string> const names = namesIn(plugin, outputs);
    std::string list;
    for (std::string const& known : names) list += (list.empty() ? "" : ", ") + known;
    std::string const meant = closestSpelling(name, names);
    return (meant.empty() ? "" : "did you mean \"" + meant + "\"? ") + (outputs ? "its outputs: " : "its parameters: ") +
           (list.empty() ? "none" : list);
}

}  // namespace

namespace {

/// An untyped parameter given the type the plugin declares for it, its values
/// checked as a typed one's are; a located error when they cannot be that type.
Param typedByPlugin(Param const& written, RixSCParamInfo const& info, std::string const& owner) {
    Param typed = written;
    ParamType const type = paramTypeFor(info.type);
    int const arraySize = info.type == k_RixSCFloat2 ? 2 : 1;
    if (!giveType(typed, type, arraySize)) {
        size_t const numbers = static_cast<size_t>(componentsOf(type) * arraySize);
        throw RibError(written.location, owner + " parameter \"" + written.name() + "\" is a " + ribTypeFor(info.type) +
                                             ", and its value cannot be one (write \"" + ribTypeFor(info.type) + " " +
                                             written.name() + "\" with " +
                                             (type == ParamType::String ? std::string("a string")
                                                                        : std::to_string(numbers) + " number" +
                                                                              (numbers > 1 ? "s" : "")) +
                                             ")");
    }
    return typed;
}

}  // namespace

NodeParams::NodeParams(std::string const& kind, ShadingPlugin const& plugin, ParamList const& params,
                       std::map<std::string, Connection> const& connections,
                       std::set<std::string> const& outputsRead, PatternLookup const& patternOf,
                       Diagnostics& diagnostics)
    : m_table(&plugin.paramTable()) {
    auto const& table = plugin.paramTable();
    m_values.resize(table.size());
    m_connections.resize(table.size());
    m_outputRead.resize(table.size());
    for (size_t i = 0; i < table.size(); ++i) {
        m_values[i].type = table[i].type;
        // A struct's members are read when the struct is ("result" reads "result.Q").
        std::string const& name = plugin.paramNames()[i];
        m_outputRead[i] = table[i].access == k_RixSCOutput &&
                          (outputsRead.count(name) || outputsRead.count(name.substr(0, name.find('.'))));
    }
    std::string const owner = kind + " \"" + plugin.name() + "\"";

    for (Param const& written : params.all()) {
        int id = plugin.paramId(written.name());
        if (id < 0 && isRendererMetadata(written.name())) continue;
        if (id < 0 || table[static_cast<size_t>(id)].access == k_RixSCOutput) {
            diagnostics.warn(written.location, owner + " has no " + (id < 0 ? "" : "input ") + "parameter \"" +
                                                   written.name() + "\"; ignored (" +
                                                   namesHint(written.name(), plugin, false) + ")");
            continue;
        }
        RixSCParamInfo const& info = table[static_cast<size_t>(id)];
        // As RenderMan types a shader's parameters from the shader, a parameter written
        // without a type takes the plugin's: "baseColor" [1 0 0] sets a color.
        Param typed;
        bool const needsType = written.decl.untyped && !written.decl.reference;
        if (needsType) typed = typedByPlugin(written, info, owner);
        Param const& p = needsType ? typed : written;
        // A struct is only ever connected. RenderMan writes an unconnected one, as exporters
        // write every default, as "struct manifold" []: the plugin keeps its own default.
        if (!p.decl.reference && !p.decl.untyped && p.decl.type == ParamType::Unknown) {
            if (!p.floats.empty() || !p.ints.empty() || !p.strings.empty())
                diagnostics.warn(p.location, owner + " parameter \"" + p.name() +
                                                 "\": a struct or filter reference holds no values, only a "
                                                 "connection (\"reference struct " + p.name() +
                                                 "\" [\"node:output\"]); ignored");
            continue;
        }
        // RenderMan's structs (a manifold) travel as a point here: see RixPattern.h.
        bool structOk = p.decl.reference && p.decl.type == ParamType::Unknown && info.type == k_RixSCPoint;
        // A reference only names its pattern: where the declaration's type and the plugin's are both
        // three floats, the connection's own types decide (below), as they do for any connection.
        bool const tripleReference = p.decl.reference && connectable(rixTypeFor(p.decl.type), info.type);
        if (tripleReference && !ribValueSets(info.type, p.decl.type))
            diagnostics.warn(p.location, owner + " parameter \"" + p.name() + "\" is a " + ribTypeFor(info.type) +
                                             ", and the RIB declares its reference a " + paramTypeName(p.decl.type) +
                                             "; connected as a " + ribTypeFor(info.type) + " (write \"reference " +
                                             ribTypeFor(info.type) + " " + p.name() + "\")");
        else if (!structOk && !ribValueSets(info.type, p.decl.type))
            throw RibError(p.location, owner + " parameter \"" + p.name() + "\" is a " + ribTypeFor(info.type) +
                                           ", but the RIB gives a " +
                                           (p.decl.type == ParamType::Unknown ? "struct" : paramTypeName(p.decl.type)) +
                                           " (write \"" + (p.decl.reference ? "reference " : "") + ribTypeFor(info.type) +
                                           " " + p.name() + "\")");
        if (p.decl.reference) {
            auto const linked = connections.find(p.name());
            PatternInstance const* source = linked == connections.end() ? nullptr : patternOf(linked->second.pattern);
            if (!source) {
                // Never declared or not loaded (both already warned): the reference's fallback, or else the
                // plugin's default.
                if (!p.fallback.empty()) {
                    m_values[static_cast<size_t>(id)].set = true;
                    m_values[static_cast<size_t>(id)].floats = p.fallback;
                }
                continue;
            }
            Connection const& link = linked->second;
            ShadingPlugin const& from = source->plugin();
            int output = from.paramId(link.output);
            if (output < 0 || from.paramTable()[static_cast<size_t>(output)].access != k_RixSCOutput)
                throw RibError(link.where, owner + " parameter \"" + p.name() + "\": pattern \"" + source->handle() +
                                               "\" (" + from.name() + ") has no output \"" + link.output +
                                               "\" (" + namesHint(link.output, from, true) + ")");
            RixSCType outType = from.paramTable()[static_cast<size_t>(output)].type;
            if (!connectable(outType, info.type))
                throw RibError(link.where, owner + " parameter \"" + p.name() + "\" is a " + ribTypeFor(info.type) +
                                               ", but \"" + source->handle() + ":" + link.output + "\" is a " +
                                               ribTypeFor(outType) + " output");
            m_connections[static_cast<size_t>(id)] = {source, output};
            continue;
        }
        ParamValue& value = m_values[static_cast<size_t>(id)];
        value.set = true;
        value.floats = p.floats;
        value.ints = p.ints;
        for (auto const& s : p.strings) value.strings.emplace_back(s.c_str());
        if (info.type == k_RixSCInteger && value.ints.empty())
            for (float f : p.floats) value.ints.push_back(static_cast<int>(f));
    }
}

int NodeParams::describe(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength) const {
    ParamValue const* given = value(id);
    if (!given) return 1;
    RixSCParamInfo const& row = (*m_table)[static_cast<size_t>(id)];
    if (type) *type = row.type;
    if (cinfo)
        *cinfo = connection(id) || m_outputRead[static_cast<size_t>(id)] ? k_RixSCNetworkValue
                 : given->set                                           ? k_RixSCParameterListValue
                                                                        : k_RixSCDefaultValue;
    if (arrayLength) {
        size_t const values = row.type == k_RixSCString    ? given->strings.size()
                              : row.type == k_RixSCInteger ? given->ints.size()
                                                           : given->floats.size();
        int const elements = static_cast<int>(values) / valuesPerElement(row.type);
        *arrayLength = row.arraySize < 0 ? -1 : given->set ? elements : row.arraySize;
    }
    return 0;
}

int NodeParameterList::GetParamId(RtUString name, int* id) const {
    for (size_t i = 0; i < m_table.size(); ++i)
        if (m_table[i].name == name && m_params.values()[i].set) {
            *id = static_cast<int>(i);
            return 0;
        }
    return 1;
}

int NodeParameterList::GetParamInfo(int id, RtUString* name, RixSCType* type) const {
    if (id < 0 || static_cast<size_t>(id) >= m_table.size()) return 1;
    if (name) *name = m_table[static_cast<size_t>(id)].name;
    if (type) *type = m_table[static_cast<size_t>(id)].type;
    return 0;
}

RixSCDetail NodeParameterList::Eval(int id, int arrayIndex, RixSCType wanted, void* result) const {
    ParamValue const* v = m_params.value(id);
    if (!v || !v->set) return k_RixSCInvalidDetail;
    size_t index = arrayIndex > 0 ? static_cast<size_t>(arrayIndex) : 0;
    bool triple = v->type == k_RixSCColor || isGeometricType(v->type);
    if (wanted == k_RixSCFloat && v->type == k_RixSCFloat && index < v->floats.size()) {
        *static_cast<float*>(result) = v->floats[index];
    } else if (wanted == k_RixSCInteger && v->type == k_RixSCInteger && index < v->ints.size()) {
        *static_cast<int*>(result) = v->ints[index];
    } else if ((wanted == k_RixSCColor || wanted == k_RixSCVector) && triple && 3 * index + 2 < v->floats.size()) {
        float* out = static_cast<float*>(result);
        for (size_t c = 0; c < 3; ++c) out[c] = v->floats[3 * index + c];
    } else if (wanted == k_RixSCString && v->type == k_RixSCString && index < v->strings.size()) {
        *static_cast<RtUString*>(result) = v->strings[index];
    } else {
        return k_RixSCInvalidDetail;
    }
    return k_RixSCUniform;
}

}  // namespace bxdflab
