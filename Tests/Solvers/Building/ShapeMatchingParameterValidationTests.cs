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

        static TestCaseData Case(string name, Spoil spoil, IssueCode code, IssueSeverity severity = IssueSeverity.Error) =>
            new TestCaseData(spoil, code, severity).SetName($"Validate_Flags_{name}");

        static IEnumerable<TestCaseData> BadFields()
        {
            yield return Case("ModeOutOfEnum", (ref ShapeMatchingParameters p) => p.Mode = (ShapeMatchingMode)7, ShapeMatchingIssueCode.ModeInvalid);
            yield return Case("FrequencyNaN", (ref ShapeMatchingParameters p) => p.Frequency = float.NaN, ParticleBodyIssueCode.ParameterNotFinite);
            yield return Case("FrequencyAboveMax", (ref ShapeMatchingParameters p) => p.Frequency = 1500f, ShapeMatchingIssueCode.FrequencyOutOfRange);
            yield return Case("FrequencyNegative", (ref ShapeMatchingParameters p) => p.Frequency = -0.1f, ShapeMatchingIssueCode.FrequencyOutOfRange);
            yield return Case("FrequencyZero", (ref ShapeMatchingParameters p) => p.Frequency = 0f, ShapeMatchingIssueCode.FrequencyZero, IssueSeverity.Warning);
            yield return Case("BetaOne", (ref ShapeMatchingParameters p) => p.Beta = 1f, ShapeMatchingIssueCode.BetaLimited, IssueSeverity.Warning);
            yield return Case("MaxSubstepPhaseZero", (ref ShapeMatchingParameters p) => p.MaxSubstepPhase = 0f, ShapeMatchingIssueCode.MaxSubstepPhaseNotPositive);
            yield return Case("MaxDepenetrationSpeedNegative", (ref ShapeMatchingParameters p) => p.Body.MaxDepenetrationSpeed = -1f, ParticleBodyIssueCode.MaxDepenetrationSpeedNotPositive);
            yield return Case("PlasticRigid", (ref ShapeMatchingParameters p) =>
            {
                p.Mode = ShapeMatchingMode.Rigid;
                p.Plasticity = new PlasticityParameters { Yield = 0.05f, Creep = 10f, MaxDeformation = 0.5f };
            }, ShapeMatchingIssueCode.PlasticityIgnoredInRigidMode, IssueSeverity.Warning);
            yield return Case("BetaAboveOne", (ref ShapeMatchingParameters p) => p.Beta = 1.01f, ShapeMatchingIssueCode.BetaOutOfRange);
            yield return Case("BetaNegative", (ref ShapeMatchingParameters p) => p.Beta = -0.01f, ShapeMatchingIssueCode.BetaOutOfRange);
            yield return Case("BetaInfinite", (ref ShapeMatchingParameters p) => p.Beta = float.PositiveInfinity, ParticleBodyIssueCode.ParameterNotFinite);
            yield return Case("DampingRatioNegative", (ref ShapeMatchingParameters p) => p.DampingRatio = -1f, ShapeMatchingIssueCode.DampingRatioOutOfRange);
            yield return Case("DampingRatioHuge", (ref ShapeMatchingParameters p) => p.DampingRatio = 1e4f, ShapeMatchingIssueCode.DampingRatioOutOfRange);
            yield return Case("AccelerationNaN", (ref ShapeMatchingParameters p) => p.Body.Acceleration.y = float.NaN, ParticleBodyIssueCode.ParameterNotFinite);
            yield return Case("SubstepsZero", (ref ShapeMatchingParameters p) => p.Body.Substeps = 0, ShapeMatchingIssueCode.SubstepsOutOfRange);
            yield return Case("SubstepsAbove64", (ref ShapeMatchingParameters p) => p.Body.Substeps = 65, ShapeMatchingIssueCode.SubstepsOutOfRange);
            yield return Case("ParticleRadiusZero", (ref ShapeMatchingParameters p) => p.Body.ParticleRadius = 0f, ParticleBodyIssueCode.ParticleRadiusInvalid);
            yield return Case("ParticleRadiusHuge", (ref ShapeMatchingParameters p) => p.Body.ParticleRadius = 1000f, ParticleBodyIssueCode.ParticleRadiusInvalid);
            yield return Case("FrictionNegative", (ref ShapeMatchingParameters p) => p.Body.Friction = -0.2f, ParticleBodyIssueCode.FrictionNegative);
            yield return Case("RestitutionAboveOne", (ref ShapeMatchingParameters p) => p.Body.Restitution = 1.2f, ParticleBodyIssueCode.RestitutionOutOfRange);
            yield return Case("RestitutionNegative", (ref ShapeMatchingParameters p) => p.Body.Restitution = -0.2f, ParticleBodyIssueCode.RestitutionOutOfRange);
            yield return Case("YieldNegative", (ref ShapeMatchingParameters p) => p.Plasticity.Yield = -0.1f, ShapeMatchingIssueCode.PlasticityNegative);
            yield return Case("CreepNegative", (ref ShapeMatchingParameters p) => p.Plasticity.Creep = -0.1f, ShapeMatchingIssueCode.PlasticityNegative);
            yield return Case("MaxDeformationNegative", (ref ShapeMatchingParameters p) => p.Plasticity.MaxDeformation = -0.1f, ShapeMatchingIssueCode.PlasticityNegative);
            yield return Case("CreepNaN", (ref ShapeMatchingParameters p) => p.Plasticity.Creep = float.NaN, ParticleBodyIssueCode.ParameterNotFinite);
            yield return Case("SleepSpeedNegative", (ref ShapeMatchingParameters p) => p.Body.SleepSpeed = -0.01f, ParticleBodyIssueCode.SleepSpeedNegative);
            yield return Case("SleepDelayNegative", (ref ShapeMatchingParameters p) => p.Body.SleepDelay = -1f, ParticleBodyIssueCode.SleepDelayNegative);
            yield return Case("MaxSpeedZero", (ref ShapeMatchingParameters p) => p.Body.MaxSpeed = 0f, ParticleBodyIssueCode.MaxSpeedNotPositive);
            yield return Case("MaxSpeedNaN", (ref ShapeMatchingParameters p) => p.Body.MaxSpeed = float.NaN, ParticleBodyIssueCode.ParameterNotFinite);
            yield return Case("RotationIterationsZero", (ref ShapeMatchingParameters p) => p.RotationIterations = 0, ParticleBodyIssueCode.RotationIterationsInvalid);
        }

        [Test]
        public void Validate_DefaultParameters_HaveNoIssues()
        {
            var issues = new List<ValidationIssue>();
            Assert.That(ShapeMatchingParameterValidation.Validate(ShapeMatchingParameters.Default, issues), Is.True);
            Assert.That(issues, Is.Empty);
        }

        [TestCaseSource(nameof(BadFields))]
        public void Validate_FlagsTheBadField(Spoil spoil, IssueCode code, IssueSeverity severity)
        {
            ShapeMatchingParameters p = ShapeMatchingParameters.Default;
            spoil(ref p);
            var issues = new List<ValidationIssue>();
            bool valid = ShapeMatchingParameterValidation.Validate(p, issues);

            Assert.That(issues.Count, Is.EqualTo(1), string.Join("; ", issues));
            Assert.That(issues[0].Code, Is.EqualTo(code));
            Assert.That(issues[0].Severity, Is.EqualTo(severity));
            Assert.That(issues[0].Index, Is.EqualTo(-1));
            Assert.That(valid, Is.EqualTo(severity == IssueSeverity.Warning), "only warnings leave the parameters valid");
        }

        [Test]
        public void Validate_NonFiniteField_IsNamedInTheMessage()
        {
            ShapeMatchingParameters p = ShapeMatchingParameters.Default;
            p.Body.SleepDelay = float.NaN;
            var issues = new List<ValidationIssue>();
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
            var issues = new List<ValidationIssue>();
            ShapeMatchingParameterValidation.Validate(p, issues);
            Assert.That(Array.ConvertAll(issues.ToArray(), i => i.Code), Is.EquivalentTo(new IssueCode[]
            {
                ShapeMatchingIssueCode.BetaOutOfRange, ShapeMatchingIssueCode.SubstepsOutOfRange, ParticleBodyIssueCode.ParameterNotFinite,
            }));
        }
    }
}
