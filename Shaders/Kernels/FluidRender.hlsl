// What the fluid renderer reads from a GPU fluid (FluidComputeStep.RecordPackRender): one float4 per slot, xyz position
// and w attribute for the live particles, NaN beyond them so the renderer's splats cull them without a live count.
#ifndef SBD_FLUID_RENDER_INCLUDED
#define SBD_FLUID_RENDER_INCLUDED
#include "FluidCommon.hlsl"

[numthreads(FLUID_GROUP, 1, 1)]
void PackRender(uint3 id : SV_DispatchThreadID)
{
    if (id.x >= _Counts.x)
        return;
    float nan = asfloat(0x7FC00000u);
    _RenderParticles[id.x] = id.x < LiveCount()
        ? float4(_Positions[id.x].xyz, asfloat(_Extras[id.x].x))
        : float4(nan, nan, nan, 0.0);
}

#endif
