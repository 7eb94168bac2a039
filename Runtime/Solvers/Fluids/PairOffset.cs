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

    /// <summary>The offset between nearest images on the periodic axes (<see cref="FluidConstants.MinimumImage"/>).</summary>
    public struct NearestImageOffset : IPairOffset
    {
        readonly float3 m_Period, m_InversePeriod;

        public NearestImageOffset(in FluidConstants c)
        {
            m_Period = c.Period;
            m_InversePeriod = c.InversePeriod;
        }

        public float3 Of(float3 xi, float3 xj)
        {
            float3 d = xi - xj;
            return d - m_Period * math.round(d * m_InversePeriod);
        }
    }
}
