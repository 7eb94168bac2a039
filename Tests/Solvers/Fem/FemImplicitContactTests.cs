using System;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>
    /// Implicit FEM holds its frictionless contact nodes in the solve (<see cref="FemImplicitEuler"/>): they rest on the
    /// collider, are released when the body leaves it, and the contacts a step starts with come from the positions alone.
    /// </summary>
    public class FemImplicitContactTests
    {
        static readonly ElasticMaterial s_Jelly = new ElasticMaterial(2e5f, 0.4f, 1000f, 0.5f);
        static readonly ColliderShape[] s_Floor = { ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) };

        static FemParameters Frictionless(FemMaterialModel model)
        {
            FemParameters p = FemParameters.Default;
            p.Integrator = FemIntegrator.ImplicitEuler;
            p.Model = model;
            p.Body.Substeps = 1;
            p.Body.Friction = 0f;
            p.CgIterations = 2000;
            p.CgTolerance = 1e-5f;
            p.Body.SleepSpeed = 0f;
            return p;
        }

        static FemTestBody RestingCube(FemMaterialModel model) =>
            new FemTestBody(FemTestBodies.Bake(FemTestBodies.Box(2, 2, 2, new float3(0.2f)), s_Jelly),
                Frictionless(model), new float3(0f, 0.1f + FemParameters.Default.Body.ParticleRadius, 0f));

        /// <summary>
        /// A cube at rest on a frictionless floor, one 1/60 s substep per step, stays on it: after 2 s every node is at most
        /// 10 µm below the contact height (the touching distance; the held nodes do not move along the normal) and the body
        /// is at rest, every speed below 1 mm/s. Without the contacts' work in the Neo-Hookean line search (<c>HeldWork</c>)
        /// the held targets shorten every Newton step and a node keeps 4.2 mm/s (measured).
        /// </summary>
        [TestCase(FemMaterialModel.CoRotational)]
        [TestCase(FemMaterialModel.NeoHookean)]
        public void RestingCube_StaysOnAFrictionlessFloor_AtRest(FemMaterialModel model)
        {
            FemTestBody body = RestingCube(model);
            float radius = body.Parameters.Body.ParticleRadius;
            for (int step = 0; step < 120; step++)
            {
                FemStepReport report = body.Step(1f / 60f, s_Floor);
                Assert.IsFalse(report.Step.Reset);
            }
            for (int i = 0; i < body.Positions.Length; i++)
            {
                Assert.That(body.Positions[i].y, Is.GreaterThanOrEqualTo(radius - ContactProjection.TouchingDistance), $"node {i}");
                Assert.That(math.length(body.Velocities[i]), Is.LessThan(1e-3f), $"node {i}");
            }
        }

        /// <summary>
        /// The cube resting on the floor, thrown up at 1 m/s, leaves it: the floor would have to pull its held nodes, so they
        /// are released, and after one step every node is above the floor by about h·(1 m/s − g h) = 14 mm (at least 10 mm):
        /// a node kept held would stay on the floor and stretch the body.
        /// </summary>
        [Test]
        public void RestingCube_ThrownUp_LeavesTheFloor()
        {
            FemTestBody body = RestingCube(FemMaterialModel.CoRotational);
            float radius = body.Parameters.Body.ParticleRadius;
            for (int step = 0; step < 30; step++)
                body.Step(1f / 60f, s_Floor);
            for (int i = 0; i < body.Velocities.Length; i++)
                body.Velocities[i] += new float3(0f, 1f, 0f);
            body.Step(1f / 60f, s_Floor);
            for (int i = 0; i < body.Positions.Length; i++)
                Assert.That(body.Positions[i].y - radius, Is.GreaterThan(0.01f), $"node {i}");
        }

        /// <summary>
        /// A step's first contacts come from the positions (<see cref="ContactProjection.StartContacts"/>), not from what the
        /// contact buffer held before the step (the ECS step's scratch is uninitialised): a step from the same positions and
        /// velocities gives the same bits whether the buffer holds the last step's contacts or random unit vectors.
        /// </summary>
        [Test]
        public void StepResult_DoesNotDependOnTheContactBufferBeforeTheStep()
        {
            FemTestBody clean = RestingCube(FemMaterialModel.NeoHookean), dirty = RestingCube(FemMaterialModel.NeoHookean);
            for (int step = 0; step < 10; step++)
            {
                clean.Step(1f / 60f, s_Floor);
                dirty.Step(1f / 60f, s_Floor);
            }
            Span<float3> normals = dirty.State.ContactNormals;
            var random = new System.Random(3);
            for (int i = 0; i < normals.Length; i++)
                normals[i] = math.normalize(new float3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, 1f));
            clean.Step(1f / 60f, s_Floor);
            dirty.Step(1f / 60f, s_Floor);
            for (int i = 0; i < clean.Positions.Length; i++)
            {
                Assert.That(dirty.Positions[i], Is.EqualTo(clean.Positions[i]), $"position {i}");
                Assert.That(dirty.Velocities[i], Is.EqualTo(clean.Velocities[i]), $"velocity {i}");
            }
        }
    }
}
