// XPBD springs (Macklin, Müller & Chentanez 2016), coloured: a port of the XPBD substep of MassSpringSolveStage and of
// SpringForces.ProjectColor. One dispatch per colour: no two springs of a colour share a particle.
#ifndef SBD_SOFT_BODY_XPBD_INCLUDED
#define SBD_SOFT_BODY_XPBD_INCLUDED
#include "SoftBodyCommon.hlsl"

// SpringForces.CoincidentFraction.
#define COINCIDENT_FRACTION 1e-6

// p = x + h v.
[numthreads(SOFT_BODY_GROUP, 1, 1)]
void XpbdPredict(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= _Range.x) return;
    _P[i] = float4(_X[i].xyz + SubstepSeconds * _V[i].xyz, 0.0);
}

// λ = 0 at the start of a substep.
[numthreads(SOFT_BODY_GROUP, 1, 1)]
void XpbdClearMultipliers(uint3 id : SV_DispatchThreadID)
{
    if (id.x < _Range.x) _Multipliers[id.x] = 0.0;
}

// SpringForces.Direction: unit vector from A to B, or the rest direction when they coincide.
float3 Direction(float3 pA, float3 pB, float3 restA, float3 restB, float restLength, out float len)
{
    float3 d = pB - pA;
    len = length(d);
    if (len > COINCIDENT_FRACTION * restLength && len > 0.0) return d / len;
    // math.normalizesafe(restB − restA, +x).
    float3 r = restB - restA;
    float l2 = dot(r, r);
    return l2 > 1.175494351e-38 ? r * rsqrt(l2) : float3(1.0, 0.0, 0.0);
}

// Eq. 18 with the damping of eq. 26 for the springs _ColorSprings[_Range.x .. _Range.y): Δλ = (−C − α̃λ − γ∇C·(p − x)) /
// ((1 + γ)(w_A + w_B) + α̃), α̃ = 1/(k h²), γ = c/(k h).
[numthreads(SOFT_BODY_GROUP, 1, 1)]
void XpbdProjectColor(uint3 id : SV_DispatchThreadID)
{
    uint k = _Range.x + id.x;
    if (k >= _Range.y) return;
    uint e = _ColorSprings[k];
    float4 s0 = _Springs[2 * e], s1 = _Springs[2 * e + 1];
    uint a = asuint(s0.x), b = asuint(s0.y);
    float restLength = s0.z, stiffness = s0.w, damping = s1.x;
    float wA = _InverseMass[a], wB = _InverseMass[b];
    if (!(stiffness > 0.0) || wA + wB == 0.0) return;
    float3 pA = _P[a].xyz, pB = _P[b].xyz;
    float len;
    float3 n = -Direction(pA, pB, _Rest[a].xyz, _Rest[b].xyz, restLength, len);
    float c = len - restLength;
    float alphaTilde = InverseSubstepSquared / stiffness;
    float gamma = damping / (stiffness * SubstepSeconds);
    float lambda = _Multipliers[e];
    float rate = dot(n, (pA - _X[a].xyz) - (pB - _X[b].xyz));
    float dLambda = (-c - alphaTilde * lambda - gamma * rate) / ((1.0 + gamma) * (wA + wB) + alphaTilde);
    _P[a] = float4(pA + wA * dLambda * n, 0.0);
    _P[b] = float4(pB - wB * dLambda * n, 0.0);
    _Multipliers[e] = lambda + dLambda;
}

// v = (p − x)/h.
[numthreads(SOFT_BODY_GROUP, 1, 1)]
void XpbdVelocities(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= _Range.x) return;
    _V[i] = float4((_P[i].xyz - _X[i].xyz) * InverseSubstep, 0.0);
}

#endif
