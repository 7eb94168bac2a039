using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>One bad field at a time on top of <see cref="ShapeMatchingParameters.Default"/>.</summary>
    public class ShapeMatchingParameterValidationTests
    {
        public delegate void Spoil(ref ShapeMatchingParameters p);

        static TestCaseData Case(string name, Spoil spoil, SoftBodyIssueCode code, SoftBodyIssueSeverity severity = SoftBodyIssueSeverity.Error) =>
            new TestCaseData(spoil, code, severity).SetName($"Validate_Flags_{name}");

        static IEnumerable<TestCaseData> BadFields()
        {
            yield return Case("ModeOutOfEnum", (ref ShapeMatchingParameters p) => p.Mode = (ShapeMatchingMode)7, SoftBodyIssueCode.ModeInvalid);
            yield return Case("FrequencyNaN", (ref ShapeMatchingParameters p) => p.Frequency = float.NaN, SoftBodyIssueCode.ParameterNotFinite);
            yield return Case("FrequencyAboveMax", (ref ShapeMatchingParameters p) => p.Frequency = 1500f, SoftBodyIssueCode.FrequencyOutOfRange);
            yield return Case("FrequencyNegative", (ref ShapeMatchingParameters p) => p.Frequency = -0.1f, SoftBodyIssueCode.FrequencyOutOfRange);
            yield return Case("FrequencyZero", (ref ShapeMatchingParameters p) => p.Frequency = 0f, SoftBodyIssueCode.FrequencyZero, SoftBodyIssueSeverity.Warning);
            yield return Case("BetaOne", (ref ShapeMatchingParameters p) => p.Beta = 1f, SoftBodyIssueCode.BetaLimited, SoftBodyIssueSeverity.Warning);
            yield return Case("MaxSubstepPhaseZero", (ref ShapeMatchingParameters p) => p.MaxSubstepPhase = 0f, SoftBodyIssueCode.MaxSubstepPhaseNotPositive);
            yield return Case("MaxDepenetrationSpeedNegative", (ref ShapeMatchingParameters p) => p.Body.MaxDepenetrationSpeed = -1f, SoftBodyIssueCode.MaxDepenetrationSpeedNotPositive);
            yield return Case("PlasticRigid", (ref ShapeMatchingParameters p) =>
            {
                p.Mode = ShapeMatchingMode.Rigid;
                p.Plasticity = new PlasticityParameters { Yield = 0.05f, Creep = 10f, MaxDeformation = 0.5f };
            }, SoftBodyIssueCode.PlasticityIgnoredInRigidMode, SoftBodyIssueSeverity.Warning);
            yield return Case("BetaAboveOne", (ref ShapeMatchingParameters p) => p.Beta = 1.01f, SoftBodyIssueCode.BetaOutOfRange);
            yield return Case("BetaNegative", (ref ShapeMatchingParameters p) => p.Beta = -0.01f, SoftBodyIssueCode.BetaOutOfRange);
            yield return Case("BetaInfinite", (ref ShapeMatchingParameters p) => p.Beta = float.PositiveInfinity, SoftBodyIssueCode.ParameterNotFinite);
            yield return Case("DampingRatioNegative", (ref ShapeMatchingParameters p) => p.DampingRatio = -1f, SoftBodyIssueCode.DampingRatioOutOfRange);
            yield return Case("DampingRatioHuge", (ref ShapeMatchingParameters p) => p.DampingRatio = 1e4f, SoftBodyIssueCode.DampingRatioOutOfRange);
            yield return Case("AccelerationNaN", (ref ShapeMatchingParameters p) => p.Body.Acceleration.y = float.NaN, SoftBodyIssueCode.ParameterNotFinite);
            yield return Case("SubstepsZero", (ref ShapeMatchingParameters p) => p.Body.Substeps = 0, SoftBodyIssueCode.SubstepsOutOfRange);
            yield return Case("SubstepsAbove64", (ref ShapeMatchingParameters p) => p.Body.Substeps = 65, SoftBodyIssueCode.SubstepsOutOfRange);
            yield return Case("ParticleRadiusZero", (ref ShapeMatchingParameters p) => p.Body.ParticleRadius = 0f, SoftBodyIssueCode.ParticleRadiusInvalid);
            yield return Case("ParticleRadiusHuge", (ref ShapeMatchingParameters p) => p.Body.ParticleRadius = 1000f, SoftBodyIssueCode.ParticleRadiusInvalid);
            yield return Case("FrictionNegative", (ref ShapeMatchingParameters p) => p.Body.Friction = -0.2f, SoftBodyIssueCode.FrictionNegative);
            yield return Case("RestitutionAboveOne", (ref ShapeMatchingParameters p) => p.Body.Restitution = 1.2f, SoftBodyIssueCode.RestitutionOutOfRange);
            yield return Case("RestitutionNegative", (ref ShapeMatchingParameters p) => p.Body.Restitution = -0.2f, SoftBodyIssueCode.RestitutionOutOfRange);
            yield return Case("YieldNegative", (ref ShapeMatchingParameters p) => p.Plasticity.Yield = -0.1f, SoftBodyIssueCode.PlasticityNegative);
            yield return Case("CreepNegative", (ref ShapeMatchingParameters p) => p.Plasticity.Creep = -0.1f, SoftBodyIssueCode.PlasticityNegative);
            yield return Case("MaxDeformationNegative", (ref ShapeMatchingParameters p) => p.Plasticity.MaxDeformation = -0.1f, SoftBodyIssueCode.PlasticityNegative);
            yield return Case("CreepNaN", (ref ShapeMatchingParameters p) => p.Plasticity.Creep = float.NaN, SoftBodyIssueCode.ParameterNotFinite);
            yield return Case("SleepSpeedNegative", (ref ShapeMatchingParameters p) => p.Body.SleepSpeed = -0.01f, SoftBodyIssueCode.SleepSpeedNegative);
            yield return Case("SleepDelayNegative", (ref ShapeMatchingParameters p) => p.Body.SleepDelay = -1f, SoftBodyIssueCode.SleepDelayNegative);
            yield return Case("MaxSpeedZero", (ref ShapeMatchingParameters p) => p.Body.MaxSpeed = 0f, SoftBodyIssueCode.MaxSpeedNotPositive);
            yield return Case("MaxSpeedNaN", (ref ShapeMatchingParameters p) => p.Body.MaxSpeed = float.NaN, SoftBodyIssueCode.ParameterNotFinite);
            yield return Case("RotationIterationsZero", (ref ShapeMatchingParameters p) => p.RotationIterations = 0, SoftBodyIssueCode.RotationIterationsInvalid);
        }

        [Test]
        public void Validate_DefaultParameters_HaveNoIssues()
        {
            var issues = new List<SoftBodyIssue>();
            Assert.That(ShapeMatchingParameterValidation.Validate(ShapeMatchingParameters.Default, issues), Is.True);
            Assert.That(issues, Is.Empty);
        }

        [TestCaseSource(nameof(BadFields))]
        public void Validate_FlagsTheBadField(Spoil spoil, SoftBodyIssueCode code, SoftBodyIssueSeverity severity)
        {
            ShapeMatchingParameters p = ShapeMatchingParameters.Default;
            spoil(ref p);
            var issues = new List<SoftBodyIssue>();
            bool valid = ShapeMatchingParameterValidation.Validate(p, issues);

            Assert.That(issues.Count, Is.EqualTo(1), string.Join("; ", issues));
            Assert.That(issues[0].Code, Is.EqualTo(code));
            Assert.That(issues[0].Severity, Is.EqualTo(severity));
            Assert.That(issues[0].Index, Is.EqualTo(-1));
            Assert.That(valid, Is.EqualTo(severity == SoftBodyIssueSeverity.Warning), "only warnings leave the parameters valid");
        }

        [Test]
        public void Validate_NonFiniteField_IsNamedInTheMessage()
        {
            ShapeMatchingParameters p = ShapeMatchingParameters.Default;
            p.Body.SleepDelay = float.NaN;
            var issues = new List<SoftBodyIssue>();
            ShapeMatchingParameterValidation.Validate(p, issues);
            Assert.That(issues.Count, Is.EqualTo(1));
            Assert.That(issues[0].Message, Does.StartWith("SleepDelay is NaN"));
        }

        [Test]
        public void Validate_ReportsEveryBadFieldAtOnce()
        {
            ShapeMatchingParameters p = ShapeMatchingParameters.Default;
            p.Beta = 2f;
            p.Body.Substeps = 0;
            p.Body.Friction = float.NaN;
            var issues = new List<SoftBodyIssue>();
            ShapeMatchingParameterValidation.Validate(p, issues);
            Assert.That(Array.ConvertAll(issues.ToArray(), i => i.Code), Is.EquivalentTo(new[]
            {
                SoftBodyIssueCode.BetaOutOfRange, SoftBodyIssueCode.SubstepsOutOfRange, SoftBodyIssueCode.ParameterNotFinite,
            }));
        }
    }
}
