// The sums of shape matching (Müller et al. 2005, eqs. 4, 5 and 7) for every cluster, one group per cluster, as parallel
// reductions in groupshared memory: the weighted centre x_cm = Σ wᵢ xᵢ / M and A_pq = Σ wᵢ (xᵢ − x_cm)(x⁰ᵢ − x⁰_cm)ᵀ
// (the sums of ClusterGoals.Compute for a cluster that has not flowed). The rest of the goal (the polar rotation) stays
// on the CPU. 64 threads per cluster (clusters hold tens of particles: a larger group would idle; a bigger cluster is
// looped over); groupshared: 3 × 64 float3 = 2.3 KB.
#ifndef SBD_SOFT_BODY_CLUSTER_SUMS_INCLUDED
#define SBD_SOFT_BODY_CLUSTER_SUMS_INCLUDED
#include "SoftBodyCommon.hlsl"

#define CLUSTER_GROUP 64

groupshared float3 s_Column0[CLUSTER_GROUP];
groupshared float3 s_Column1[CLUSTER_GROUP];
groupshared float3 s_Column2[CLUSTER_GROUP];

// Tree reduction of the three arrays into element 0.
void Reduce(uint local)
{
    for (uint stride = CLUSTER_GROUP / 2; stride > 0; stride >>= 1)
    {
        if (local < stride)
        {
            s_Column0[local] += s_Column0[local + stride];
            s_Column1[local] += s_Column1[local + stride];
            s_Column2[local] += s_Column2[local + stride];
        }
        GroupMemoryBarrierWithGroupSync();
    }
}

[numthreads(CLUSTER_GROUP, 1, 1)]
void ClusterSums(uint3 group : SV_GroupID, uint local : SV_GroupIndex)
{
    uint c = group.x;
    uint start = _ClusterOffsets[c], end = _ClusterOffsets[c + 1];
    float4 rest = _ClusterRest[c];
    // Eq. 4/5: the weighted centre.
    float3 sum = float3(0.0, 0.0, 0.0);
    for (uint k = start + local; k < end; k += CLUSTER_GROUP)
        sum += _ClusterWeights[k] * _X[_ClusterParticles[k]].xyz;
    s_Column0[local] = sum;
    s_Column1[local] = float3(0.0, 0.0, 0.0);
    s_Column2[local] = float3(0.0, 0.0, 0.0);
    GroupMemoryBarrierWithGroupSync();
    Reduce(local);
    float3 centre = rest.w > 0.0 ? s_Column0[0] / rest.w : float3(0.0, 0.0, 0.0);
    GroupMemoryBarrierWithGroupSync();
    // Eq. 7: A_pq = Σ wᵢ pᵢ qᵢᵀ, column j = Σ wᵢ pᵢ qᵢⱼ.
    float3 a0 = float3(0.0, 0.0, 0.0), a1 = a0, a2 = a0;
    for (uint k2 = start + local; k2 < end; k2 += CLUSTER_GROUP)
    {
        uint i = _ClusterParticles[k2];
        float w = _ClusterWeights[k2];
        float3 p = _X[i].xyz - centre;
        float3 q = _Rest[i].xyz - rest.xyz;
        a0 += w * p * q.x;
        a1 += w * p * q.y;
        a2 += w * p * q.z;
    }
    s_Column0[local] = a0;
    s_Column1[local] = a1;
    s_Column2[local] = a2;
    GroupMemoryBarrierWithGroupSync();
    Reduce(local);
    if (local == 0)
    {
        _ClusterCenters[c] = float4(centre, 0.0);
        _ClusterApq[3 * c] = float4(s_Column0[0], 0.0);
        _ClusterApq[3 * c + 1] = float4(s_Column1[0], 0.0);
        _ClusterApq[3 * c + 2] = float4(s_Column2[0], 0.0);
    }
}

#endif
