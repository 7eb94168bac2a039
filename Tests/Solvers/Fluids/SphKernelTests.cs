using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The kernels and their half-space integrals against numerical quadrature in float64.</summary>
    public class SphKernelTests
    {
        const float k_H = 0.04f;

        // Midpoint rule with 4000 radial steps: the integrands are polynomials of degree ≤ 7 in r, so the error is
        // O(Δr²) ≈ 1e-7 relative, far below the float32 round-off (1e-6) of the kernel evaluations.
        [Test]
        public void Poly6_IntegratesToOne()
        {
            var k = new SphKernels(k_H);
            int steps = 4000;
            double dr = k_H / steps, sum = 0;
            for (int i = 0; i < steps; i++)
            {
                double r = (i + 0.5) * dr;
                sum += 4 * Math.PI * r * r * k.Poly6((float)(r * r)) * dr;
            }
            Assert.That(sum, Is.EqualTo(1.0).Within(1e-5));
        }

        /// <summary>
        /// ∫_{z>d} f(r, z) dV over the half-space beyond a plane at distance d, in cylindrical shells: the midpoint rule on a
        /// 600² grid of (z, ρ), Σ f(√(ρ² + z²), z)·2πρ·dρ·dz, points beyond h left out.
        /// </summary>
        static double HalfSpaceIntegral(double d, Func<double, double, double> f)
        {
            int steps = 600;
            double dz = (k_H - d) / steps, dp = k_H / steps, sum = 0;
            for (int iz = 0; iz < steps; iz++)
            {
                double z = d + (iz + 0.5) * dz;
                for (int ip = 0; ip < steps; ip++)
                {
                    double rho = (ip + 0.5) * dp, r = Math.Sqrt(rho * rho + z * z);
                    if (r < k_H)
                        sum += f(r, z) * 2 * Math.PI * rho * dp * dz;
                }
            }
            return sum;
        }

        /// <summary>The spiky kernel's dW/dr = −45/(πh⁶)(h − r)².</summary>
        static double SpikyDerivative(double r) => -45.0 / (Math.PI * Math.Pow(k_H, 6)) * (k_H - r) * (k_H - r);

        [TestCase(0.0)]
        [TestCase(0.25)]
        [TestCase(0.5)]
        [TestCase(0.9)]
        public void WallDensityFraction_IsTheHalfSpaceIntegralOfPoly6(double u)
        {
            var k = new SphKernels(k_H);
            double d = u * k_H;
            double sum = HalfSpaceIntegral(d, (r, z) => k.Poly6((float)(r * r)));
            // Midpoint error on a 600² grid of a kernel with a kink-free cutoff: about 1e-5 of the integral's scale 1.
            Assert.That(k.WallDensityFraction((float)d), Is.EqualTo(sum).Within(2e-5));
        }

        [TestCase(0.0)]
        [TestCase(0.3)]
        [TestCase(0.7)]
        public void WallGradientMagnitude_IsTheHalfSpaceIntegralOfTheSpikyGradient(double u)
        {
            // The normal component of ∫_{z>d} ∇W dV: ∂W/∂z = (dW/dr)·z/r.
            var k = new SphKernels(k_H);
            double d = u * k_H;
            double sum = HalfSpaceIntegral(d, (r, z) => SpikyDerivative(r) * z / r);
            // The integral's scale is 1.5/h = 37.5 1/m; the spiky gradient is discontinuous at r = 0 only in direction,
            // so the midpoint error stays ~1e-4 relative.
            Assert.That(k.WallGradientMagnitude((float)d), Is.EqualTo(-sum).Within(1e-3 * 1.5 / k_H));
        }

        [Test]
        public void Kernels_AreZeroOutsideTheSupportAndForNaN()
        {
            var k = new SphKernels(k_H);
            Assert.AreEqual(0f, k.Poly6(k_H * k_H));
            Assert.AreEqual(0f, k.Poly6(float.NaN));
            Assert.AreEqual(0f, k.SpikyGradientScale(float.NaN));
            Assert.AreEqual(0f, k.ViscosityLaplacian(float.NaN));
            Assert.AreEqual(0f, k.Cohesion(k_H));
            Assert.That(k.ViscosityLaplacian(0.5f * k_H), Is.GreaterThan(0f));
            // Akinci's spline is repulsive (negative) near 0 and attractive (positive) beyond about h/3.
            Assert.That(k.Cohesion(0.1f * k_H), Is.LessThan(0f));
            Assert.That(k.Cohesion(0.6f * k_H), Is.GreaterThan(0f));
        }
    }
}
