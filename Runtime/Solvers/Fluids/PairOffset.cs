using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The offset xᵢ − xⱼ of a particle pair as a pass sees it. The passes take it as a struct type parameter, so each
    /// compiles once per kind (Burst and the .NET JIT specialise value types) and a domain without periodic axes pays no
    /// branch per pair.
    /// </summary>
    public interface IPairOffset
    {
        /// <summary>xᵢ − xⱼ (m).</summary>
        float3 Of(float3 xi, float3 xj);
    }

    /// <summary>The plain offset xᵢ − xⱼ: a domain without periodic axes.</summary>
    public struct DirectOffset : IPairOffset
    {
        public float3 Of(float3 xi, float3 xj) => xi - xj;
    }

    /// <summary>The offset between nearest images on the periodic axes (minimum image: each component within half a period).</summary>
    public struct NearestImageOffset : IPairOffset
    {
        readonly float3 m_Period, m_InversePeriod;

        public NearestImageOffset(in FluidConstants c)
        {
            m_Period = c.Period;
            m_InversePeriod = c.InversePeriod;
        }

        public float3 Of(float3 xi, float3 xj) => Apply(xi - xj, m_Period, m_InversePeriod);

        /// <summary><paramref name="d"/> moved by whole periods (<paramref name="period"/>, 0 on an axis that is not periodic, and its inverse) to the nearest image.</summary>
        public static float3 Apply(float3 d, float3 period, float3 inversePeriod) => d - period * math.round(d * inversePeriod);
    }
}
