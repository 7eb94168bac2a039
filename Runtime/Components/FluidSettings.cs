using SoftBodyDynamics.Solvers;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics
{
    /// <summary>
    /// A fluid (baked from <c>FluidAuthoring</c>): its solver settings and particle budget. Its particles live in the
    /// fluid entity's buffers (packed storage, <see cref="FluidPosition"/> and the rest); the
    /// <see cref="FluidSimulationSystem"/> runs only while a fluid exists.
    /// </summary>
    public struct FluidSettings : IComponentData
    {
        /// <summary>Solver settings (units in <see cref="FluidParameters"/>).</summary>
        public FluidParameters Parameters;
        /// <summary>Most particles the fluid holds (the buffers' length).</summary>
        public int Budget;
        /// <summary>Base colour of the look, linear RGBA (from the preset).</summary>
        public float4 Color;
        /// <summary>Packed (buffers only) or one entity per particle.</summary>
        public FluidStorage Storage;
        /// <summary>Entities storage: the particle prefab (with <see cref="FluidParticle"/>) new particles are instantiated from.</summary>
        public Entity ParticlePrefab;
        /// <summary>CPU (Burst jobs), GPU (compute shaders, with a fallback) or Auto (see <see cref="FluidBackendChoice"/>). Packed storage only.</summary>
        public FluidBackend Backend;
        /// <summary>GPU: when the particles are copied back into the entity buffers.</summary>
        public FluidReadback Readback;
        /// <summary>GPU, <see cref="FluidReadback.EveryNFrames"/>: fixed steps between read-backs (≥ 1).</summary>
        public int ReadbackInterval;
    }

    /// <summary>The fluid's counters and what its last frame did.</summary>
    public struct FluidRuntime : IComponentData
    {
        /// <summary>Live particles and the spawned / killed / expired / invalid totals.</summary>
        public FluidStatus Status;
        /// <summary>The last frame: solver step report, drained, spawned, held back, over budget.</summary>
        public FluidFrameReport LastFrame;
        /// <summary>The buffers have been sized to the budget.</summary>
        public bool Initialized;
        /// <summary>The taps' prewarm has run.</summary>
        public bool Prewarmed;
    }
}
