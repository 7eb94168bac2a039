// The counting sort of a substep (FluidPasses.Keys, Sort and FluidSolver.SortParticles): keys with removal, a
// histogram whose atomic ranks are then made stable (StableRanks), the scan (FluidScan.hlsl), the scatter and the
// permutation. Slots of dead particles get the key past every cell and so fall off the end: the
// sort is also the stream compaction.
#ifndef SBD_FLUID_SORT_INCLUDED
#define SBD_FLUID_SORT_INCLUDED
#include "FluidCommon.hlsl"

// Zeroes the step's counters (the live count and the totals stay).
[numthreads(16, 1, 1)]
void ClearStats(uint3 id : SV_DispatchThreadID)
{
    if ((id.x > STAT_LIVE && id.x < STAT_TOTAL_KILLED) || (id.x >= STAT_MAX_HEIGHT && id.x < STAT_COUNT)) _Stats[id.x] = 0;
}

// FluidSolver.Begin: ages += dt and the fastest finite speed (as the bits of v², which order like the floats);
// position-based also the extent along gravity (FluidSolver.Depth): height s = (x clamped to the box − DomainMin)·(−ĝ) in [−L, L],
// L the domain's diagonal, kept as the maxima of s + L and L − s (non-negative, so their bits order like the floats).
[numthreads(FLUID_GROUP, 1, 1)]
void BeginStep(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    _Positions[i].w += StepSeconds;
    float3 v = _Velocities[i].xyz;
    float v2 = dot(v, v);
    if (v2 > 0.0 && v2 <= FLOAT_MAX) InterlockedMax(_Stats[STAT_MAX_SPEED_SQUARED], asuint(v2));
    float g = length(Gravity);
    float3 x = _Positions[i].xyz;
    if (WeaklyCompressible == 0 && g > 0.0 && IsFinite3(x))
    {
        float s = dot(clamp(x, DomainMin, DomainMax) - DomainMin, -Gravity / g);
        float L = length(DomainMax - DomainMin);
        if (s >= -L && s <= L)
        {
            InterlockedMax(_Stats[STAT_MAX_HEIGHT], asuint(s + L));
            InterlockedMax(_Stats[STAT_MIN_HEIGHT_MIRRORED], asuint(L - s));
        }
    }
}

// Zeroes the histogram: _Counts.z entries of _CellStart (cells + 2).
[numthreads(FLUID_GROUP, 1, 1)]
void ClearCells(uint3 id : SV_DispatchThreadID)
{
    if (id.x < _Counts.z) _CellStart[id.x] = 0;
}

// FluidPasses.Keys, and the slot's rank among those of its key (histogram in _CellStart[key + 1]).
[numthreads(FLUID_GROUP, 1, 1)]
void Keys(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    float4 xa = _Positions[i];
    float4 vl = _Velocities[i];
    float life = vl.w;
    uint key;
    uint removed = STAT_COUNT;
    if (life < 0.0 || isnan(life)) removed = STAT_KILLED;
    else if (life > 0.0 && xa.w >= life) removed = STAT_EXPIRED;
    else if (!IsFinite3(xa.xyz) || !IsFinite3(vl.xyz)) removed = STAT_INVALID;
    if (removed != STAT_COUNT)
    {
        key = CellCount;
        InterlockedAdd(_Stats[removed], 1);
        InterlockedAdd(_Stats[removed + (STAT_TOTAL_KILLED - STAT_KILLED)], 1);
    }
    else key = KeyOf(CellOf(xa.xyz));
    _Keys[i] = key;
    uint rank;
    InterlockedAdd(_CellStart[key + 1], 1, rank);
    _Ranks[i] = rank;
}

// Order[CellStart[key] + rank] = slot.
[numthreads(FLUID_GROUP, 1, 1)]
void Scatter(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    _Order[_CellStart[_Keys[i]] + _Ranks[i]] = i;
}

// The atomic ranks follow no order: a slot's stable rank is the number of slots of its cell with a smaller index, counted
// over the cell's entries that Scatter wrote (read only here, so no slot waits on another). Scattering again with these
// ranks gives the stable counting sort's order, the CPU's bit for bit. A cell of k particles costs k reads per particle.
[numthreads(FLUID_GROUP, 1, 1)]
void StableRanks(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    if (i >= LiveCount()) return;
    uint key = _Keys[i];
    uint begin = _CellStart[key], end = _CellStart[key + 1];
    uint rank = 0;
    for (uint m = begin; m < end; m++)
        rank += _Order[m] < i ? 1 : 0;
    _Ranks[i] = rank;
}

// The live count (slots with a cell key) and the indirect arguments of the particle kernels.
[numthreads(1, 1, 1)]
void CommitSort(uint3 id : SV_DispatchThreadID)
{
    uint live = _CellStart[CellCount];
    _Stats[STAT_LIVE] = live;
    _Args[0] = (live + FLUID_GROUP - 1) / FLUID_GROUP;
    _Args[1] = 1;
    _Args[2] = 1;
}

// Out[k] = In[Order[k]] for the live slots: the gather half of FluidPasses.Permute (with _Previous when asked).
void Gather(uint k, bool previous)
{
    uint j = _Order[k];
    _PositionsOut[k] = _Positions[j];
    _VelocitiesOut[k] = _Velocities[j];
    _ExtrasOut[k] = _Extras[j];
    if (previous) _PreviousOut[k] = _Previous[j];
}

[numthreads(FLUID_GROUP, 1, 1)]
void Permute(uint3 id : SV_DispatchThreadID)
{
    if (id.x < LiveCount()) Gather(id.x, false);
}

[numthreads(FLUID_GROUP, 1, 1)]
void PermuteWithPrevious(uint3 id : SV_DispatchThreadID)
{
    if (id.x < LiveCount()) Gather(id.x, true);
}

// In[k] = Out[k]: the copy half of the permutation (so every kernel keeps the same buffers bound).
[numthreads(FLUID_GROUP, 1, 1)]
void PermuteCopyBack(uint3 id : SV_DispatchThreadID)
{
    uint k = id.x;
    if (k >= LiveCount()) return;
    _Positions[k] = _PositionsOut[k];
    _Velocities[k] = _VelocitiesOut[k];
    _Extras[k] = _ExtrasOut[k];
}

[numthreads(FLUID_GROUP, 1, 1)]
void PermuteCopyBackWithPrevious(uint3 id : SV_DispatchThreadID)
{
    uint k = id.x;
    if (k >= LiveCount()) return;
    _Positions[k] = _PositionsOut[k];
    _Velocities[k] = _VelocitiesOut[k];
    _Extras[k] = _ExtrasOut[k];
    _Previous[k] = _PreviousOut[k];
}

// Appends _Counts.y particles from the spawn buffers (in _PositionsOut, _VelocitiesOut, _ExtrasOut) after the live
// ones, as far as the capacity _Counts.x allows.
[numthreads(FLUID_GROUP, 1, 1)]
void Emit(uint3 id : SV_DispatchThreadID)
{
    uint i = id.x;
    uint slot = LiveCount() + i;
    if (i >= _Counts.y || slot >= _Counts.x) return;
    _Positions[slot] = _PositionsOut[i];
    _Velocities[slot] = _VelocitiesOut[i];
    _Extras[slot] = _ExtrasOut[i];
}

// The live count after Emit, and the indirect arguments.
[numthreads(1, 1, 1)]
void CommitEmit(uint3 id : SV_DispatchThreadID)
{
    uint live = min(LiveCount() + _Counts.y, _Counts.x);
    _Stats[STAT_LIVE] = live;
    _Args[0] = (live + FLUID_GROUP - 1) / FLUID_GROUP;
    _Args[1] = 1;
    _Args[2] = 1;
}

#endif
