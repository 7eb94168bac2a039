// Buffers and constants of the soft-body kernels (a port of the data of MassSpringModel and ShapeMatchingModel).
// Vectors are float4 (no float3 in structured buffers).
#ifndef SBD_SOFT_BODY_COMMON_INCLUDED
#define SBD_SOFT_BODY_COMMON_INCLUDED

#include "SoftBodyComputeConstants.hlsl"

#define SOFT_BODY_GROUP 256

RWStructuredBuffer<float4> _X;              // positions at the start of the substep (m)
RWStructuredBuffer<float4> _V;              // velocities (m/s)
RWStructuredBuffer<float4> _P;              // predicted positions (m)
RWStructuredBuffer<float4> _Rest;           // rest positions (m)
RWStructuredBuffer<float> _InverseMass;     // 1/m (1/kg), 0 = pinned
RWStructuredBuffer<float4> _Springs;        // two per spring: (A bits, B bits, rest length m, stiffness N/m), (damping N·s/m, 0, 0, 0)
RWStructuredBuffer<uint> _ColorSprings;     // spring indices grouped by colour (GraphColoring)
RWStructuredBuffer<float> _Multipliers;     // XPBD λ per spring
RWStructuredBuffer<uint> _ClusterOffsets;   // clusters + 1
RWStructuredBuffer<uint> _ClusterParticles;
RWStructuredBuffer<float> _ClusterWeights;
RWStructuredBuffer<float4> _ClusterRest;    // per cluster: rest centre (m), total mass (kg)
RWStructuredBuffer<float4> _ClusterCenters; // per cluster: centre of the positions (m)
RWStructuredBuffer<float4> _ClusterApq;     // per cluster: A_pq as three columns

// Per-dispatch argument (set before each dispatch, SoftBodyComputeStep).
uint4 _Range;    // x first, y end (colour range in _ColorSprings, or the particle / spring / cluster count in x), zw unused

#endif
