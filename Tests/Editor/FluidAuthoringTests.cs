using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>What the fluid, tap and drain bakers store: presets, world-space placement and validation.</summary>
    public class FluidAuthoringTests
    {
        readonly List<Object> m_Created = new List<Object>();

        [TearDown]
        public void TearDown()
        {
            foreach (Object created in m_Created)
                if (created != null)
                    Object.DestroyImmediate(created);
            m_Created.Clear();
        }

        T Create<T>(string name) where T : Component
        {
            var gameObject = new GameObject(name);
            m_Created.Add(gameObject);
            return gameObject.AddComponent<T>();
        }

        [Test]
        public void Fluid_PresetSetsTheMaterial_AndTheDomainFollowsTheTransform()
        {
            FluidAuthoring fluid = Create<FluidAuthoring>("Fluid");
            fluid.transform.position = new Vector3(1f, 2f, 3f);
            fluid.domainSize = new Vector3(2f, 4f, 6f);
            fluid.preset = FluidAuthoringPreset.Honey;
            fluid.restDensity = 5f;
            FluidParameters p = fluid.ToParameters();
            Assert.AreEqual(FluidPresets.Get(FluidPresetKind.Honey).Parameters.RestDensity, p.RestDensity, "the preset wins over the custom field");
            Assert.AreEqual(new float3(0f, 0f, 0f), p.DomainMin);
            Assert.AreEqual(new float3(2f, 4f, 6f), p.DomainMax);
            fluid.preset = FluidAuthoringPreset.Custom;
            Assert.AreEqual(5f, fluid.ToParameters().RestDensity);
            var issues = new List<ValidationIssue>();
            Assert.IsTrue(FluidValidation.Validate(fluid.ToParameters(), fluid.particleBudget, issues));
            fluid.restDensity = -1f;
            Assert.IsFalse(FluidValidation.Validate(fluid.ToParameters(), fluid.particleBudget, issues));
            Assert.AreEqual((IssueCode)FluidIssueCode.DensityInvalid, issues[issues.Count - 1].Code);
        }

        [Test]
        public void Tap_StoresItsWorldPose_AndOverBudgetIsAnError()
        {
            FluidAuthoring fluid = Create<FluidAuthoring>("Fluid");
            fluid.particleBudget = 100;
            FluidTapAuthoring tap = Create<FluidTapAuthoring>("Tap");
            tap.fluid = fluid;
            tap.transform.position = new Vector3(0f, 1f, 0f);
            FluidTapSettings s = tap.ToSettings();
            Assert.AreEqual(new float3(0f, 1f, 0f), s.Position);
            tap.rate = 100f;
            tap.lifetime = 5f;
            var issues = new List<ValidationIssue>();
            Assert.IsFalse(FluidValidation.ValidateTap(tap.ToSettings(), tap.bursts, fluid.particleSpacing, fluid.particleBudget, issues));
            Assert.AreEqual((IssueCode)FluidEmissionIssueCode.TapOverBudget, issues[0].Code, "100/s × 5 s = 500 alive > budget 100");
            Assert.That(tap.SteadyStateAlive(), Is.EqualTo(500.0).Within(1e-6));
        }

        [Test]
        public void Drain_IsTheScaledBoxInWorldSpace()
        {
            FluidDrainAuthoring drain = Create<FluidDrainAuthoring>("Drain");
            drain.transform.position = new Vector3(0f, 0.5f, 0f);
            drain.transform.localScale = new Vector3(2f, 2f, 2f);
            drain.size = new Vector3(0.2f, 0.1f, 0.2f);
            FluidDrain d = drain.ToDrain();
            Assert.AreEqual(ColliderShapeType.Box, d.Shape.Type);
            Assert.AreEqual(new float3(0f, 0.5f, 0f), d.Shape.Center);
            Assert.That(d.Shape.HalfExtents.y, Is.EqualTo(0.1f).Within(1e-6f));
        }
    }
}
