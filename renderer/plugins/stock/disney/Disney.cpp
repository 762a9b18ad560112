#include "Disney.h"

#include <cmath>

#include "RixShadingUtils.h"

DisneyLobes g_disneyLobes;

namespace {

float pow5(float x) { return (x * x) * (x * x) * x; }
float schlickWeight(float cosTheta) { return pow5(RixClamp(1.0f - cosTheta, 0.0f, 1.0f)); }

/// A direction in the point's tangent frame: (along u, along v, along N).
struct Local {
    float x, y, z;
};
Local toLocal(Disney::Point const& p, RtVector3 const& w) { return {w.Dot(p.u), w.Dot(p.v), w.Dot(p.N)}; }
RtVector3 fromLocal(Disney::Point const& p, Local const& w) { return p.u * w.x + p.v * w.y + p.N * w.z; }

// ---------------------------------------------------------------- GGX (specular)

float ggxD(Local const& h, float au, float av) {
    float x = h.x / au, y = h.y / av;
    float s = x * x + y * y + h.z * h.z;
    return 1.0f / (F_PI * au * av * s * s);
}

float ggxLambda(Local const& w, float au, float av) {
    float z2 = w.z * w.z;
    if (z2 <= 0.0f) return 0.0f;
    float t = ((au * w.x) * (au * w.x) + (av * w.y) * (av * w.y)) / z2;
    return 0.5f * (std::sqrt(1.0f + t) - 1.0f);
}

/// Pdf of L when H is drawn from the visible normals seen from V: G1(V) D(H) (V.H) / cos_V / (4 V.H).
float ggxVisiblePdf(Local const& v, Local const& h, float au, float av) {
    if (v.z <= 0.0f) return 0.0f;
    float g1 = 1.0f / (1.0f + ggxLambda(v, au, av));
    return g1 * ggxD(h, au, av) / (4.0f * v.z);
}

/// Heitz (2018): a microfacet normal from the GGX normals visible from v (v.z > 0).
Local sampleGgxVisibleNormal(Local const& v, float au, float av, RtFloat2 const& xi) {
    // Stretch the view so the distribution becomes the unit hemisphere's.
    float sx = au * v.x, sy = av * v.y, sz = v.z;
    float len = std::sqrt(sx * sx + sy * sy + sz * sz);
    sx /= len, sy /= len, sz /= len;
    // An orthonormal basis around the stretched view.
    float lensq = sx * sx + sy * sy;
    float t1x = 1.0f, t1y = 0.0f;
    if (lensq > 0.0f) {
        float inv = 1.0f / std::sqrt(lensq);
        t1x = -sy * inv, t1y = sx * inv;
    }
    // T2 = stretched view x T1.
    float t2x = -sz * t1y, t2y = sz * t1x, t2z = sx * t1y - sy * t1x;
    // A point on the disk, warped toward the part of the hemisphere the view sees.
    float r = std::sqrt(xi[0]), phi = F_TWOPI * xi[1];
    float p1 = r * std::cos(phi), p2 = r * std::sin(phi);
    float s = 0.5f * (1.0f + sz);
    p2 = (1.0f - s) * std::sqrt(RixMax(0.0f, 1.0f - p1 * p1)) + s * p2;
    float p3 = std::sqrt(RixMax(0.0f, 1.0f - p1 * p1 - p2 * p2));
    float nx = p1 * t1x + p2 * t2x + p3 * sx;
    float ny = p1 * t1y + p2 * t2y + p3 * sy;
    float nz = p2 * t2z + p3 * sz;
    // Unstretch.
    Local h{au * nx, av * ny, RixMax(0.0f, nz)};
    float hl = std::sqrt(h.x * h.x + h.y * h.y + h.z * h.z);
    return {h.x / hl, h.y / hl, h.z / hl};
}

// ---------------------------------------------------------------- GTR1 (clearcoat)

float gtr1D(float cosH, float a) {
    float a2 = a * a;
    return (a2 - 1.0f) / (F_PI * std::log(a2) * (1.0f + (a2 - 1.0f) * cosH * cosH));
}

float clearcoatG1(float cosTheta) {
    Local w{std::sqrt(RixMax(0.0f, 1.0f - cosTheta * cosTheta)), 0.0f, cosTheta};
    return 1.0f / (1.0f + ggxLambda(w, 0.25f, 0.25f));
}

/// cos(theta_h) of a GTR1 half vector: the inverse of its cumulative distribution.
float sampleGtr1CosTheta(float a, float xi) {
    float a2 = a * a;
    return std::sqrt(RixMax(0.0f, (1.0f - std::pow(a2, 1.0f - xi)) / (1.0f - a2)));
}

/// The hue of a colour at unit luminance (white when it is black).
RtColorRGB tintOf(RtColorRGB const& c) {
    float lum = c.Luminance();
    return lum > 0.0f ? c * (1.0f / lum) : RtColorRGB(1.0f);
}

RtColorRGB mix(RtColorRGB const& a, RtColorRGB const& b, float t) { return a * (1.0f - t) + b * t; }

}  // namespace

Disney::Disney(RixShadingContext const* sc, RixBxdfFactory* factory, DisneyParams const& params)
    : RixBxdf(sc, factory), m_params(params) {
    sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
    sc->GetBuiltinVar(RixShadingContext::k_Ngn, &m_Ngn);
    sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
    // The tangent costs time to compute: only an anisotropic highlight needs it.
    if (params.anyAnisotropic) sc->GetBuiltinVar(RixShadingContext::k_Tn, &m_Tn);
}

Disney::Point Disney::point(int i) const {
    Point p;
    RtNormal3 const* bent = m_params.bumpNormal;
    bool const isBent = bent && bent[i].LengthSq() > 1e-12f;
    p.N = RixGetForwardFacingNormal(m_Vn[i], isBent ? RtNormal3(Normalize(bent[i])) : m_Nn[i]);
    RixComputeShadingBasis(p.N, m_Tn ? m_Tn[i] : RtVector3(0.0f), p.u, p.v);

    RtColorRGB base = m_params.baseColor[i];
    float metallic = RixClamp(m_params.metallic[i], 0.0f, 1.0f);
    RtColorRGB tint = tintOf(base);
    p.diffuseColor = base * (1.0f - metallic);
    p.sheenColor = mix(RtColorRGB(1.0f), tint, m_params.sheenTint[i]) * (RixMax(m_params.sheen[i], 0.0f) * (1.0f - metallic));
    RtColorRGB dielectric = mix(RtColorRGB(1.0f), tint, m_params.specularTint[i]) * (0.08f * RixMax(m_params.specular[i], 0.0f));
    p.specular0 = mix(dielectric, base, metallic);
    p.subsurface = RixClamp(m_params.subsurface[i], 0.0f, 1.0f);
    p.subsurfaceColor = m_params.subsurfaceColor[i] * (1.0f - metallic);
    p.roughness = RixClamp(m_params.roughness[i], 0.0f, 1.0f);
    float aspect = std::sqrt(1.0f - 0.9f * RixClamp(m_params.anisotropic[i], 0.0f, 1.0f));
    float alpha = p.roughness * p.roughness;
    p.alphaU = RixMax(0.001f, alpha / aspect);
    p.alphaV = RixMax(0.001f, alpha * aspect);
    p.clearcoat = 0.25f * RixMax(m_params.clearcoat[i], 0.0f);
    p.clearcoatAlpha = RixMix(0.1f, 0.001f, RixClamp(m_params.clearcoatGloss[i], 0.0f, 1.0f));

    // Selection probabilities from rough albedo estimates: Schlick's Fresnel
    // averaged over the cosine-weighted hemisphere is C0 + (1 - C0) / 21.
    float diffuse = (mix(p.diffuseColor, p.subsurfaceColor, p.subsurface) + p.sheenColor * 0.1f).Luminance();
    float specular = (p.specular0 + (RtColorRGB(1.0f) - p.specular0) * (1.0f / 21.0f)).Luminance();
    float clearcoat = p.clearcoat * (0.04f + 0.96f / 21.0f);
    float total = RixMax(diffuse, 0.0f) + RixMax(specular, 0.0f) + clearcoat;
    p.pDiffuse = total > 0.0f ? RixMax(diffuse, 0.0f) / total : 1.0f;
    p.pSpecular = total > 0.0f ? RixMax(specular, 0.0f) / total : 0.0f;
    p.pClearcoat = total > 0.0f ? clearcoat / total : 0.0f;
    return p;
}

bool Disney::EmitLocal(RtColorRGB* result) {
    bool any = false;
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        result[i] = m_params.emitColor[i];
        any = any || !result[i].IsBlack();
    }
    return any;
}

namespace {

/// The mixture pdf of choosing `to` when looking from `from` (both unit, away from the surface).
float mixturePdf(Disney::Point const& p, RtVector3 const& from, RtVector3 const& to) {
    Local v = toLocal(p, from), l = toLocal(p, to);
    if (l.z <= 0.0f || v.z <= 0.0f) return 0.0f;
    RtVector3 Hw = Normalize(from + to);
    Local h = toLocal(p, Hw);
    float vh = from.Dot(Hw);
    float pdf = p.pDiffuse * l.z * F_INVPI;
    if (h.z > 0.0f && vh > 0.0f) {
        pdf += p.pSpecular * ggxVisiblePdf(v, h, p.alphaU, p.alphaV);
        if (p.pClearcoat > 0.0f) pdf += p.pClearcoat * gtr1D(h.z, p.clearcoatAlpha) * h.z / (4.0f * vh);
    }
    return pdf;
}

}  // namespace

bool Disney::evaluate(int i, RtVector3 const& L, RtColorRGB& diffuse, RtColorRGB& specular, RtColorRGB& clearcoat,
                      float& fpdf, float& rpdf) const {
    diffuse = specular = clearcoat = RtColorRGB(0.0f);
    fpdf = rpdf = 0.0f;
    Point p = point(i);
    RtVector3 const& V = m_Vn[i];
    RtNormal3 Ng = RixGetForwardFacingNormal(V, m_Ngn[i]);
    float cosL = p.N.Dot(L), cosV = p.N.Dot(V);
    if (cosL <= 0.0f || cosV <= 0.0f || Ng.Dot(L) <= 0.0f) return false;
    RtVector3 Hw = Normalize(L + V);
    float LdotH = RixClamp(L.Dot(Hw), 0.0f, 1.0f);
    float FL = schlickWeight(cosL), FV = schlickWeight(cosV), FH = schlickWeight(LdotH);

    // Diffuse: Burley's retro-reflective term, blended with the flattened one.
    float fd90 = 0.5f + 2.0f * p.roughness * LdotH * LdotH;
    float fd = (1.0f + (fd90 - 1.0f) * FL) * (1.0f + (fd90 - 1.0f) * FV);
    float fss90 = p.roughness * LdotH * LdotH;
    float fss = (1.0f + (fss90 - 1.0f) * FL) * (1.0f + (fss90 - 1.0f) * FV);
    float ss = 1.25f * (fss * (1.0f / (cosL + cosV) - 0.5f) + 0.5f);
    diffuse = p.diffuseColor * ((1.0f - p.subsurface) * fd * F_INVPI * cosL) +
              p.subsurfaceColor * (p.subsurface * ss * F_INVPI * cosL) + p.sheenColor * (FH * cosL);

    // Specular: D F G / (4 cos_L cos_V), times cos_L.
    Local l = toLocal(p, L), v = toLocal(p, V), h = toLocal(p, Hw);
    if (h.z > 0.0f) {
        float D = ggxD(h, p.alphaU, p.alphaV);
        float G = 1.0f / (1.0f + ggxLambda(l, p.alphaU, p.alphaV) + ggxLambda(v, p.alphaU, p.alphaV));
        RtColorRGB F = p.specular0 + (RtColorRGB(1.0f) - p.specular0) * FH;
        specular = F * (D * G / (4.0f * cosV));
        if (p.clearcoat > 0.0f) {
            float Dc = gtr1D(h.z, p.clearcoatAlpha);
            float Fc = 0.04f + 0.96f * FH;
            float Gc = clearcoatG1(cosL) * clearcoatG1(cosV);
            clearcoat = RtColorRGB(p.clearcoat * Dc * Fc * Gc / (4.0f * cosV));
        }
    }
    fpdf = mixturePdf(p, V, L);
    rpdf = mixturePdf(p, L, V);
    return true;
}

void Disney::GenerateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                            RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                            float* RPdf, RtColorRGB*) {
    int const n = shadingCtx->numPts;
    RtColorRGB* diffuseW = W.AddActiveLobe(g_disneyLobes.diffuse);
    RtColorRGB* specularW = W.AddActiveLobe(g_disneyLobes.specular);
    RtColorRGB* clearcoatW = W.AddActiveLobe(g_disneyLobes.clearcoat);
    RixBXLobeTraits const all = GetAllLobeTraits();
    float* choice = static_cast<float*>(RixAlloca(sizeof(float) * n));
    RtFloat2* xi = static_cast<RtFloat2*>(RixAlloca(sizeof(RtFloat2) * n));
    rng->DrawSamples1D(choice);
    rng->DrawSamples2D(xi);

    for (int i = 0; i < n; ++i) {
        lobeSampled[i].SetValid(false);
        FPdf[i] = RPdf[i] = 0.0f;
        Ln[i] = RtVector3(0.0f);
        if (!(all & lobesWanted[i] & g_disneyLobes.all).HasAny()) continue;
        Point p = point(i);
        Local v = toLocal(p, m_Vn[i]);
        if (v.z <= 0.0f) continue;
        RixBXLobeSampled chosen;
        if (choice[i] < p.pDiffuse) {
            float cosTheta;
            RixCosDirectionalDistribution(xi[i], p.N, p.u, p.v, Ln[i], cosTheta);
            chosen = g_disneyLobes.diffuse;
        } else {
            Local h;
            if (choice[i] < p.pDiffuse + p.pSpecular) {
                h = sampleGgxVisibleNormal(v, p.alphaU, p.alphaV, xi[i]);
                chosen = g_disneyLobes.specular;
            } else {
                float cosH = sampleGtr1CosTheta(p.clearcoatAlpha, xi[i][0]);
                float sinH = std::sqrt(RixMax(0.0f, 1.0f - cosH * cosH)), phi = F_TWOPI * xi[i][1];
                h = {sinH * std::cos(phi), sinH * std::sin(phi), cosH};
                chosen = g_disneyLobes.clearcoat;
            }
            Ln[i] = RixReflect(-m_Vn[i], fromLocal(p, h));  // mirror V about H
        }
        bool reflects = evaluate(i, Ln[i], diffuseW[i], specularW[i], clearcoatW[i], FPdf[i], RPdf[i]);
        if (!reflects || !(FPdf[i] > 0.0f)) continue;  // below the surface: an invalid sample
        lobeSampled[i] = chosen;
        lobeSampled[i].SetValid(true);
    }
}

void Disney::EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG*,
                            RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf,
                            float* RPdf) {
    RtColorRGB* diffuseW = W.AddActiveLobe(g_disneyLobes.diffuse);
    RtColorRGB* specularW = W.AddActiveLobe(g_disneyLobes.specular);
    RtColorRGB* clearcoatW = W.AddActiveLobe(g_disneyLobes.clearcoat);
    RixBXLobeTraits const all = GetAllLobeTraits();
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        lobesEvaluated[i].SetNone();
        FPdf[i] = RPdf[i] = 0.0f;
        if ((all & lobesWanted[i] & g_disneyLobes.all).HasAny() &&
            evaluate(i, Ln[i], diffuseW[i], specularW[i], clearcoatW[i], FPdf[i], RPdf[i])) {
            lobesEvaluated[i] |= g_disneyLobes.all;
            lobesEvaluated[i].SetValid(true);
        }
    }
}

void Disney::EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const& lobesWanted, RixRNG*, int index,
                                    int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                    RixBXLobeWeights& W, float* FPdf, float* RPdf) {
    RtColorRGB* diffuseW = W.AddActiveLobe(g_disneyLobes.diffuse);
    RtColorRGB* specularW = W.AddActiveLobe(g_disneyLobes.specular);
    RtColorRGB* clearcoatW = W.AddActiveLobe(g_disneyLobes.clearcoat);
    bool const wanted = (GetAllLobeTraits() & lobesWanted & g_disneyLobes.all).HasAny();
    for (int s = 0; s < numSamples; ++s) {
        lobesEvaluated[s].SetNone();
        FPdf[s] = RPdf[s] = 0.0f;
        if (wanted && evaluate(index, Ln[s], diffuseW[s], specularW[s], clearcoatW[s], FPdf[s], RPdf[s])) {
            lobesEvaluated[s] |= g_disneyLobes.all;
            lobesEvaluated[s].SetValid(true);
        }
    }
}
