using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The SPH smoothing kernels of Müller, Charypar &amp; Gross 2003 (poly6 for density, spiky for the pressure
    /// gradient, the viscosity kernel's Laplacian), Akinci et al. 2013's cohesion spline, and the integrals of poly6
    /// and of spiky's gradient over a half-space (a wall of fluid-density matter at distance d), all for kernel
    /// radius h. Coefficients are computed once on the CPU (<see cref="SphKernels(float)"/>); every function takes
    /// squared or plain distances so the hot loops avoid square roots where they can.
    /// </summary>
    public readonly struct SphKernels
    {
        /// <summary>Kernel radius h (m).</summary>
        public readonly float H;
        /// <summary>h² (m²).</summary>
        public readonly float H2;
        /// <summary>Poly6 coefficient 315 / (64 π h⁹).</summary>
        public readonly float Poly6Coefficient;
        /// <summary>Spiky gradient coefficient −45 / (π h⁶).</summary>
        public readonly float SpikyGradientCoefficient;
        /// <summary>Viscosity-kernel Laplacian coefficient 45 / (π h⁶).</summary>
        public readonly float ViscosityLaplacianCoefficient;
        /// <summary>Akinci cohesion spline coefficient 32 / (π h⁹).</summary>
        public readonly float CohesionCoefficient;
        /// <summary>Akinci spline offset h⁶ / 64 for r ≤ h/2.</summary>
        public readonly float CohesionOffset;

        public SphKernels(float h)
        {
            H = h;
            H2 = h * h;
            float h3 = h * h * h;
            float h6 = h3 * h3;
            float h9 = h6 * h3;
            Poly6Coefficient = 315f / (64f * math.PI * h9);
            SpikyGradientCoefficient = -45f / (math.PI * h6);
            ViscosityLaplacianCoefficient = 45f / (math.PI * h6);
            CohesionCoefficient = 32f / (math.PI * h9);
            CohesionOffset = h6 / 64f;
        }

        /// <summary>Poly6 W(r) = 315/(64πh⁹)·(h² − r²)³ for r &lt; h (Müller 2003, eq. 20), from r² (1/m³).</summary>
        public float Poly6(float r2)
        {
            // Written as !(r² < h²) so that a NaN distance (a removed particle) contributes nothing.
            if (!(r2 < H2))
                return 0f;
            float d = H2 - r2;
            return Poly6Coefficient * d * d * d;
        }

        /// <summary>
        /// Spiky gradient ∇W(r) = −45/(πh⁶)·(h − r)²·r̂ (Müller 2003, eq. 21) as the scalar to multiply the offset
        /// vector r = xᵢ − xⱼ by: ∇W = SpikyGradientScale(r)·r (1/m⁵). Zero at r = 0 (no direction) and r ≥ h.
        /// </summary>
        public float SpikyGradientScale(float r)
        {
            if (!(r < H) || !(r > 0f))
                return 0f;
            float d = H - r;
            return SpikyGradientCoefficient * d * d / r;
        }

        /// <summary>Viscosity-kernel Laplacian ∇²W(r) = 45/(πh⁶)·(h − r) for r &lt; h (Müller 2003, eq. 22), 1/m⁵.</summary>
        public float ViscosityLaplacian(float r) => !(r < H) ? 0f : ViscosityLaplacianCoefficient * (H - r);

        /// <summary>
        /// Akinci et al. 2013 cohesion spline C(r) (eq. 2): 32/(πh⁹)·(h − r)³r³ for h/2 &lt; r ≤ h, and
        /// 32/(πh⁹)·(2(h − r)³r³ − h⁶/64) for 0 &lt; r ≤ h/2 (1/m³); zero otherwise.
        /// </summary>
        public float Cohesion(float r)
        {
            if (!(r < H) || !(r > 0f))
                return 0f;
            float a = (H - r) * r;
            float c = a * a * a;
            return CohesionCoefficient * (2f * r > H ? c : 2f * c - CohesionOffset);
        }

        /// <summary>
        /// ∫ W dV of poly6 over the half-space beyond a plane at distance <paramref name="d"/> from the kernel's centre
        /// (dimensionless, ½ at d = 0, 0 at d ≥ h): the density a wall of rest-density matter adds, as a fraction of ρ₀.
        /// With u = d/h: ½ − (315/256)·(u − 4u³/3 + 6u⁵/5 − 4u⁷/7 + u⁹/9), the closed form of
        /// (π/4)·315/(64πh⁹)·∫_d^h (h² − z²)⁴ dz.
        /// </summary>
        public float WallDensityFraction(float d)
        {
            if (d >= H)
                return 0f;
            float u = math.max(d, 0f) / H;
            float u2 = u * u;
            float f = u * (1f + u2 * (-4f / 3f + u2 * (6f / 5f + u2 * (-4f / 7f + u2 * (1f / 9f)))));
            return 0.5f - 315f / 256f * f;
        }

        /// <summary>
        /// |∫ ∇W dV| of the spiky kernel over the half-space beyond a plane at distance <paramref name="d"/> (1/m):
        /// 2π·∫_d^h W_spiky(r)·r dr = (30/h)·((1 − u)⁴/4 − (1 − u)⁵/5) with u = d/h: the derivative with respect to d
        /// of the spiky kernel's half-space integral. The gradient points from the particle into the wall.
        /// </summary>
        public float WallGradientMagnitude(float d)
        {
            if (d >= H)
                return 0f;
            float s = 1f - math.max(d, 0f) / H;
            float s4 = s * s * s * s;
            return 30f / H * (s4 / 4f - s4 * s / 5f);
        }
    }
}
