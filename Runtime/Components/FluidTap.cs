using SoftBodyDynamics.Solvers;
using Unity.Entities;

namespace SoftBodyDynamics
{
    /// <summary>A tap (emitter) of a fluid, baked from <c>FluidTapAuthoring</c>. Up to four bursts are stored inline.</summary>
    public struct FluidTap : IComponentData
    {
        /// <summary>Shape, flow, timing and lifetime (units in <see cref="FluidTapSettings"/>), in world space.</summary>
        public FluidTapSettings Settings;
        /// <summary>The fluid entity it pours into.</summary>
        public Entity Fluid;
        /// <summary>Bursts in use (0–4).</summary>
        public int BurstCount;
        public FluidTapBurst Burst0, Burst1, Burst2, Burst3;

        /// <summary>Most bursts a tap stores.</summary>
        public const int MaxBursts = 4;

        /// <summary>Burst <paramref name="index"/> (0–3).</summary>
        public FluidTapBurst Burst(int index) => index == 0 ? Burst0 : index == 1 ? Burst1 : index == 2 ? Burst2 : Burst3;

        /// <summary>Sets burst <paramref name="index"/> (0–3).</summary>
        public void SetBurst(int index, FluidTapBurst burst)
        {
            if (index == 0) Burst0 = burst;
            else if (index == 1) Burst1 = burst;
            else if (index == 2) Burst2 = burst;
            else Burst3 = burst;
        }
    }

    /// <summary>A drain (kill volume) of a fluid, baked from <c>FluidDrainAuthoring</c>.</summary>
    public struct FluidDrainVolume : IComponentData
    {
        /// <summary>The volume in world space.</summary>
        public FluidDrain Drain;
        /// <summary>The fluid entity it drains.</summary>
        public Entity Fluid;
    }
}
