// Inclusive prefix sum of _Counts.z uints in blocks of SCAN_BLOCK elements per group, one level per dispatch: level 0
// is the cell histogram (_CellStart), the levels above are the block totals, stored one after another in _ScanSums
// (FluidComputeLayout.ScanLevels). Plain groupshared Hillis–Steele steps with barriers: no wave intrinsics, so no
// assumption on the wave size.
#ifndef SBD_FLUID_SCAN_INCLUDED
#define SBD_FLUID_SCAN_INCLUDED
#include "FluidCommon.hlsl"

#define SCAN_THREADS 256
#define SCAN_BLOCK 512

groupshared uint s_Scan[SCAN_BLOCK];

uint ScanLoad(bool cells, uint index) { return cells ? _CellStart[index] : _ScanSums[index]; }

void ScanStore(bool cells, uint index, uint value)
{
    if (cells) _CellStart[index] = value;
    else _ScanSums[index] = value;
}

// Scans each block of the level (elements from _Counts.w) in place; its total goes to _ScanSums[_Scan.x + block].
void ScanBlock(bool cells, uint block, uint local)
{
    uint n = _Counts.z, offset = _Counts.w;
    uint a = block * SCAN_BLOCK + local, b = a + SCAN_THREADS;
    s_Scan[local] = a < n ? ScanLoad(cells, offset + a) : 0;
    s_Scan[local + SCAN_THREADS] = b < n ? ScanLoad(cells, offset + b) : 0;
    GroupMemoryBarrierWithGroupSync();
    for (uint step = 1; step < SCAN_BLOCK; step <<= 1)
    {
        // HLSL evaluates both arms of ?:, so the index stays in range on both (an out-of-range groupshared read is undefined).
        uint upper = local + SCAN_THREADS;
        uint lo = local >= step ? s_Scan[local >= step ? local - step : local] : 0;
        uint hi = upper >= step ? s_Scan[upper >= step ? upper - step : upper] : 0;
        GroupMemoryBarrierWithGroupSync();
        s_Scan[local] += lo;
        s_Scan[local + SCAN_THREADS] += hi;
        GroupMemoryBarrierWithGroupSync();
    }
    if (a < n) ScanStore(cells, offset + a, s_Scan[local]);
    if (b < n) ScanStore(cells, offset + b, s_Scan[local + SCAN_THREADS]);
    if (local == SCAN_THREADS - 1) _ScanSums[_Scan.x + block] = s_Scan[SCAN_BLOCK - 1];
}

[numthreads(SCAN_THREADS, 1, 1)]
void ScanCellBlocks(uint3 group : SV_GroupID, uint local : SV_GroupIndex) { ScanBlock(true, group.x, local); }

[numthreads(SCAN_THREADS, 1, 1)]
void ScanSumBlocks(uint3 group : SV_GroupID, uint local : SV_GroupIndex) { ScanBlock(false, group.x, local); }

// Adds the scanned total of the blocks before each element's block (the level above, already scanned, at _Scan.x).
void AddOffset(bool cells, uint e)
{
    if (e >= _Counts.z || e < SCAN_BLOCK) return;
    uint index = _Counts.w + e;
    ScanStore(cells, index, ScanLoad(cells, index) + _ScanSums[_Scan.x + e / SCAN_BLOCK - 1]);
}

[numthreads(SCAN_THREADS, 1, 1)]
void AddCellOffsets(uint3 id : SV_DispatchThreadID) { AddOffset(true, id.x); }

[numthreads(SCAN_THREADS, 1, 1)]
void AddSumOffsets(uint3 id : SV_DispatchThreadID) { AddOffset(false, id.x); }

#endif
