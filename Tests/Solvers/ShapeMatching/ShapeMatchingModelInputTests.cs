using System;
using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// The public creation APIs of shape matching reject what the step cannot use with a specific error, as mass-spring and
    /// FEM do: particle masses, rest positions and clusters of the model, and the material of the calibration.
    /// </summary>
    public class ShapeMatchingModelInputTests
    {
        static readonly float3[] s_Rest = { new float3(0f), new float3(1f, 0f, 0f), new float3(0f, 1f, 0f), new float3(0f, 0f, 1f) };
        static readonly int[] s_Offsets = { 0, 4 };
        static readonly int[] s_Members = { 0, 1, 2, 3 };

        [Test]
        public void ValidInput_IsAccepted()
        {
            ShapeMatchingModelData model = ShapeMatchingModelData.Create(s_Rest, new[] { 1f, 1f, 1f, 1f }, s_Offsets, s_Members, false);
            Assert.AreEqual(4, model.ParticleCount);
        }

        [TestCase(0f)]
        [TestCase(-1f)]
        [TestCase(float.NaN)]
        [TestCase(float.PositiveInfinity)]
        public void BadMass_IsRejected_NamingTheParticle(float mass)
        {
            var e = Assert.Throws<ArgumentException>(() => ShapeMatchingModelData.Create(s_Rest, new[] { 1f, 1f, mass, 1f }, s_Offsets, s_Members, false));
            StringAssert.StartsWith("Mass 2 is", e.Message);
            Assert.AreEqual("masses", e.ParamName);
        }

        [Test]
        public void MassCountOtherThanTheParticles_IsRejected() =>
            Assert.Throws<ArgumentException>(() => ShapeMatchingModelData.Create(s_Rest, new[] { 1f, 1f, 1f }, s_Offsets, s_Members, false));

        [Test]
        public void NonFiniteRestPosition_IsRejected()
        {
            var rest = (float3[])s_Rest.Clone();
            rest[3] = new float3(0f, float.NaN, 0f);
            var e = Assert.Throws<ArgumentException>(() => ShapeMatchingModelData.Create(rest, new[] { 1f, 1f, 1f, 1f }, s_Offsets, s_Members, false));
            StringAssert.StartsWith("Rest position 3 is", e.Message);
        }

        [TestCase(new[] { 1, 4 }, new[] { 0, 1, 2, 3 }, "clusterOffsets")]
        [TestCase(new[] { 0, 5 }, new[] { 0, 1, 2, 3 }, "clusterOffsets")]
        [TestCase(new[] { 0, 3, 2 }, new[] { 0, 1, 2, 3 }, "clusterOffsets")]
        [TestCase(new[] { 0, 4 }, new[] { 0, 1, 2, 4 }, "clusterParticles")]
        [TestCase(new[] { 0, 4 }, new[] { 0, -1, 2, 3 }, "clusterParticles")]
        public void BadClusters_AreRejected(int[] offsets, int[] members, string parameter)
        {
            var e = Assert.Throws<ArgumentException>(() => ShapeMatchingModelData.Create(s_Rest, new[] { 1f, 1f, 1f, 1f }, offsets, members, false));
            Assert.AreEqual(parameter, e.ParamName);
        }

        [TestCase(1e6f, 0.5f, 1100f, 0.1f)]
        [TestCase(1e6f, -0.1f, 1100f, 0.1f)]
        [TestCase(0f, 0.3f, 1100f, 0.1f)]
        [TestCase(1e6f, 0.3f, float.NaN, 0.1f)]
        [TestCase(1e6f, 0.3f, 1100f, -0.1f)]
        public void Calibration_RejectsTheMaterialsMassSpringAndFemReject(float e, float nu, float rho, float zeta)
        {
            var material = new ElasticMaterial(e, nu, rho, zeta);
            Assert.IsFalse(material.IsValid);
            var error = Assert.Throws<ArgumentException>(() =>
                ShapeMatchingCalibration.For(material, 0.1f, ShapeMatchingCalibration.Load.Compression, ShapeMatchingMode.Linear,
                    ShapeMatchingParameters.Default));
            Assert.AreEqual("material", error.ParamName);
        }

        [TestCase(0f)]
        [TestCase(-0.1f)]
        [TestCase(float.NaN)]
        public void Calibration_RejectsABadLength(float length) =>
            Assert.Throws<ArgumentException>(() => ShapeMatchingCalibration.For(ElasticMaterial.Rubber, length,
                ShapeMatchingCalibration.Load.Compression, ShapeMatchingMode.Linear, ShapeMatchingParameters.Default));

        /// <summary>
        /// A compact body in compression: f is the quarter wave √(E/ρ) / (4H) of a column on its base, and ζ_SM is the material's
        /// ζ (float32 round-off only).
        /// </summary>
        [Test]
        public void Calibration_OfACompactBody_IsTheColumnsSlowestMode()
        {
            ElasticMaterial m = ElasticMaterial.Rubber;
            ShapeMatchingParameters p = ShapeMatchingCalibration.For(m, 0.1f, ShapeMatchingCalibration.Load.Compression, ShapeMatchingMode.Linear,
                ShapeMatchingParameters.Default);
            Assert.That(p.Frequency, Is.EqualTo(Math.Sqrt(m.YoungsModulus / m.Density) / (4.0 * 0.1)).Within(1e-4).Percent);
            Assert.That(p.DampingRatio, Is.EqualTo(m.DampingRatio));
            Assert.That(p.Beta, Is.EqualTo(ShapeMatchingCalibration.Beta));
        }

        /// <summary>A slender body in bending takes the fitted coefficient and the beam's slowest-mode ratio.</summary>
        [Test]
        public void Calibration_OfABeam_GivesTheFittedFrequency()
        {
            ShapeMatchingParameters p = ShapeMatchingCalibration.For(ElasticMaterial.Rubber, 3.2f, ShapeMatchingCalibration.Load.Bending,
                ShapeMatchingMode.Linear, ShapeMatchingParameters.Default);
            Assert.AreEqual(ShapeMatchingCalibration.Frequency(ElasticMaterial.Rubber, 3.2f, ShapeMatchingCalibration.LinearCoefficient), p.Frequency);
            Assert.AreEqual(ElasticMaterial.Rubber.DampingRatio * ShapeMatchingCalibration.SlowestModeRatio, p.DampingRatio);
        }

        /// <summary>
        /// A frequency above <see cref="ShapeMatchingParameters.MaxFrequency"/> is refused with the number, instead of running
        /// silently at the cap (rubber as a 10 cm beam would need 8.4 kHz).
        /// </summary>
        [Test]
        public void Calibration_RefusesAFrequencyAboveTheLimit()
        {
            var error = Assert.Throws<ArgumentException>(() => ShapeMatchingCalibration.For(ElasticMaterial.Rubber, 0.1f,
                ShapeMatchingCalibration.Load.Bending, ShapeMatchingMode.Linear, ShapeMatchingParameters.Default));
            StringAssert.Contains("Hz", error.Message);
            Assert.DoesNotThrow(() => ShapeMatchingCalibration.For(StabilityCube.StiffMaterial, StabilityCube.DefaultSize,
                ShapeMatchingCalibration.Load.Compression, ShapeMatchingMode.Linear, ShapeMatchingParameters.Default));
        }
    }
}
