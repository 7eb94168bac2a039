using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Core;
using Unity.Entities;
using Unity.Mathematics;
using Unity.Transforms;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>
    /// The soft-body systems in a test world: initialization at the entity transform, falling and
    /// landing on a collider, the NaN guard, impulses, independence of bodies, and running only when a
    /// soft body exists. Each update steps both systems once with a fixed dt and completes the jobs.
    /// </summary>
    public class ShapeMatchingSystemTests
    {
        const float k_Dt = 1f / 60f;
        const float k_Spacing = 0.1f;

        World m_World;
        EntityManager m_Manager;
        SystemHandle m_Initialization;
        SystemHandle m_Simulation;
        SystemHandle m_ColliderWorld;
        BlobAssetReference<ShapeMatchingShapeBlob> m_Shape;
        ShapeMatchingModelData m_Model;
        double m_ElapsedTime;

        /// <summary>
        /// A 3×3×3 lattice (spacing 0.1 m, 1 kg) standing on its mesh origin: rest positions span
        /// y ∈ [0, 0.2] m, so the rest centre of mass is (0, 0.1, 0) and the pivot is not the centre.
        /// Eight overlapping 2×2×2 clusters.
        /// </summary>
        static ShapeMatchingModelData CubeLattice()
        {
            var rest = new List<float3>();
            for (int z = 0; z < 3; z++)
            for (int y = 0; y < 3; y++)
            for (int x = 0; x < 3; x++)
                rest.Add(k_Spacing * new float3(x - 1, y, z - 1));
            var masses = new float[rest.Count];
            for (int i = 0; i < masses.Length; i++)
                masses[i] = 1f / masses.Length;

            var offsets = new List<int> { 0 };
            var members = new List<int>();
            for (int cz = 0; cz < 2; cz++)
            for (int cy = 0; cy < 2; cy++)
            for (int cx = 0; cx < 2; cx++)
            {
                for (int z = cz; z < cz + 2; z++)
                for (int y = cy; y < cy + 2; y++)
                for (int x = cx; x < cx + 2; x++)
                    members.Add(x + 3 * (y + 3 * z));
                offsets.Add(members.Count);
            }
            return ShapeMatchingModelData.Create(rest.ToArray(), masses, offsets.ToArray(), members.ToArray(), false);
        }

        [SetUp]
        public void SetUp()
        {
            m_World = new World("Soft body system tests");
            m_Manager = m_World.EntityManager;
            m_ColliderWorld = m_World.CreateSystem<ColliderWorldSystem>();
            m_Initialization = m_World.CreateSystem<ShapeMatchingInitializationSystem>();
            m_Simulation = m_World.CreateSystem<ShapeMatchingSimulationSystem>();
            m_Model = CubeLattice();
            m_Shape = ShapeMatchingShapeBlobFactory.Create(m_Model, null, null, Allocator.Persistent);
            m_ElapsedTime = 0.0;
        }

        [TearDown]
        public void TearDown()
        {
            m_Manager.CompleteAllTrackedJobs();
            m_World.Dispose();
            // Blobs made outside baking belong to their creator.
            if (m_Shape.IsCreated)
                m_Shape.Dispose();
        }

        Entity CreateBody(float3 position, quaternion rotation, ShapeMatchingParameters parameters)
        {
            Entity entity = m_Manager.CreateEntity();
            m_Manager.AddComponentData(entity, LocalTransform.FromPositionRotation(position, rotation));
            SoftBodyArchetype.AddComponents(m_Manager, entity, m_Shape, parameters);
            return entity;
        }

        Entity CreateBody(float3 position) => CreateBody(position, quaternion.identity, ShapeMatchingParameters.Default);

        void Update(int frames = 1)
        {
            for (int f = 0; f < frames; f++)
            {
                m_ElapsedTime += k_Dt;
                m_World.SetTime(new TimeData(m_ElapsedTime, k_Dt));
                m_ColliderWorld.Update(m_World.Unmanaged);
                m_Initialization.Update(m_World.Unmanaged);
                m_Simulation.Update(m_World.Unmanaged);
                m_Manager.CompleteAllTrackedJobs();
            }
        }

        float3[] Positions(Entity entity)
        {
            DynamicBuffer<SoftBodyPosition> buffer = m_Manager.GetBuffer<SoftBodyPosition>(entity, true);
            var x = new float3[buffer.Length];
            for (int i = 0; i < x.Length; i++)
                x[i] = buffer[i].Value;
            return x;
        }

        static void AssertAllFinite(float3[] positions)
        {
            for (int i = 0; i < positions.Length; i++)
                Assert.That(math.all(math.isfinite(positions[i])), Is.True, $"particle {i} is finite: {positions[i]}");
        }

        ParticleBodyStatus Status(Entity entity) => m_Manager.GetComponentData<ParticleBodyState>(entity).Status;

        [Test]
        public void SimulationSystem_RunsOnlyWhenASoftBodyExists()
        {
            Assert.That(m_World.Unmanaged.ResolveSystemStateRef(m_Simulation).ShouldRunSystem(), Is.False,
                "no soft body: the simulation does not update");
            Assert.That(m_World.Unmanaged.ResolveSystemStateRef(m_Initialization).ShouldRunSystem(), Is.False);

            CreateBody(float3.zero);

            Assert.That(m_World.Unmanaged.ResolveSystemStateRef(m_Simulation).ShouldRunSystem(), Is.True);
            Assert.That(m_World.Unmanaged.ResolveSystemStateRef(m_Initialization).ShouldRunSystem(), Is.True);
        }

        [Test]
        public void InitializationSystem_PlacesTheRestShape_AtTheEntityTransform()
        {
            float3 position = new float3(1f, 2f, 3f);
            quaternion rotation = quaternion.AxisAngle(new float3(0f, 1f, 0f), 0.5f * math.PI);
            Entity body = CreateBody(position, rotation, ShapeMatchingParameters.Default);

            m_Initialization.Update(m_World.Unmanaged);
            m_Manager.CompleteAllTrackedJobs();

            Assert.That(m_Manager.IsComponentEnabled<SoftBodyUninitialized>(body), Is.False, "initialised once");
            float3[] x = Positions(body);
            Assert.That(x.Length, Is.EqualTo(m_Model.ParticleCount));
            Assert.That(m_Manager.GetBuffer<ShapeMatchingCluster>(body, true).Length, Is.EqualTo(m_Model.ClusterCount));
            for (int i = 0; i < x.Length; i++)
            {
                float3 expected = position + math.rotate(rotation, m_Model.RestPositions[i]);
                Assert.That(math.distance(x[i], expected), Is.LessThan(1e-5f), $"particle {i}: {x[i]} vs {expected}");
            }
            DynamicBuffer<SoftBodyVelocity> v = m_Manager.GetBuffer<SoftBodyVelocity>(body, true);
            for (int i = 0; i < v.Length; i++)
                Assert.That(v[i].Value.Equals(float3.zero), Is.True, "starts at rest");

            float3 expectedCenter = position + math.rotate(rotation, m_Model.BodyRest.RestCenter);
            Assert.That(math.distance(Status(body).Center, expectedCenter), Is.LessThan(1e-5f));
            LocalTransform transform = m_Manager.GetComponentData<LocalTransform>(body);
            Assert.That(math.distance(transform.Position, position), Is.LessThan(1e-6f), "the mesh origin stays put");
            Assert.That(transform.Scale, Is.EqualTo(1f));
        }

        [Test]
        public void Body_FallsUnderGravity_AndStaysFinite()
        {
            ShapeMatchingParameters parameters = ShapeMatchingParameters.Default;
            Entity body = CreateBody(new float3(0f, 5f, 0f), quaternion.identity, parameters);
            float startY = 5f + m_Model.BodyRest.RestCenter.y;

            Update(30);

            // The solver integrates semi-implicitly (v += h·a, then x += h·v) over N substeps of h, which moves
            // the centre of mass by a·h²·N(N+1)/2 exactly: the shape-matching pull is internal and the damping
            // spares rigid motion. (The continuous ½·a·t² differs from it by a·h·t/2 ≈ 1 cm.) Round-off: N
            // position updates at |y| ≤ 5.1 m, each within half an ulp (2.4e-7 m), stay below 3e-5 m.
            int substeps = ShapeMatchingSolver.SubstepCount(parameters, k_Dt);
            int n = 30 * substeps;
            double h = (double)k_Dt / substeps;
            float expectedY = (float)(startY + parameters.Body.Acceleration.y * h * h * n * (n + 1) / 2.0);
            ParticleBodyStatus status = Status(body);
            Assert.That(status.Center.y, Is.EqualTo(expectedY).Within(1e-4f), "free fall of the centre of mass");
            Assert.That(status.ResetCount, Is.EqualTo(0));
            ParticleStepReport shared = m_Manager.GetComponentData<ParticleBodyState>(body).LastReport;
            ShapeMatchingStepReport full = m_Manager.GetComponentData<ShapeMatchingDiagnostics>(body).LastReport;
            Assert.That(shared.Stepped, Is.True);
            Assert.That(full.Stepped, Is.True, "the diagnostics hold the same step's full report");
            Assert.That(full.Substeps, Is.EqualTo(substeps));
            Assert.That(shared.Substeps, Is.EqualTo(full.Substeps));
            AssertAllFinite(Positions(body));

            LocalTransform transform = m_Manager.GetComponentData<LocalTransform>(body);
            float3 pivot = status.Center - math.rotate(status.Rotation, m_Model.BodyRest.RestCenter);
            Assert.That(math.distance(transform.Position, pivot), Is.LessThan(1e-5f), "the entity follows the body");
        }

        [Test]
        public void WorldSettings_ReplaceEveryBodysGravityAndRaiseItsSubsteps()
        {
            ShapeMatchingParameters parameters = ShapeMatchingParameters.Default;
            parameters.Body.Substeps = 1;
            parameters.MaxSubstepPhase = 1000f; // exactly the requested substeps
            Entity body = CreateBody(new float3(0f, 5f, 0f), quaternion.identity, parameters);
            Entity world = m_Manager.CreateEntity();
            var settings = new ParticleWorldSettings { Gravity = new float3(1f, 0f, 0f), MinSubsteps = 3 };
            m_Manager.AddComponentData(world, settings);
            float3 start = new float3(0f, 5f, 0f) + m_Model.BodyRest.RestCenter;

            Update(10);

            // Sideways "gravity" of 1 m/s² over 10 steps of 3 substeps: x moves by a·h²·N(N+1)/2 (see the free-fall test), y not at all.
            int n = 30;
            double h = (double)k_Dt / 3;
            ParticleBodyStatus status = Status(body);
            Assert.That(m_Manager.GetComponentData<ParticleBodyState>(body).LastReport.Substeps, Is.EqualTo(3), "the world's minimum substeps");
            Assert.That(status.Center.x, Is.EqualTo((float)(start.x + h * h * n * (n + 1) / 2.0)).Within(1e-5f), "the world's gravity");
            Assert.That(status.Center.y, Is.EqualTo(start.y).Within(1e-5f), "the body's own gravity is replaced");
        }

        [Test]
        public void Body_LandsOnAGroundCollider_AndStaysAboveIt()
        {
            Entity ground = m_Manager.CreateEntity();
            m_Manager.AddComponentData(ground, new ParticleCollider { Shape = ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) });
            Entity body = CreateBody(new float3(0f, 0.5f, 0f));

            Update(180);

            float3[] x = Positions(body);
            AssertAllFinite(x);
            // The contact projection is the last move of every substep and leaves each particle centre at
            // least its radius above the plane; 1e-5 m covers float32 round-off at |y| ≈ 0.02 m.
            float radius = ShapeMatchingParameters.Default.Body.ParticleRadius;
            foreach (float3 p in x)
                Assert.That(p.y, Is.GreaterThanOrEqualTo(radius - 1e-5f), "no particle sinks into the ground");
            Assert.That(Status(body).Center.y, Is.LessThan(0.25f), "the body fell onto the ground");
        }

        [Test]
        public void NaNInAPositionBuffer_IsResetWithinOneUpdate_AndReported()
        {
            Entity body = CreateBody(new float3(0f, 2f, 0f));
            Update(2);
            ParticleBodyStatus before = Status(body);

            DynamicBuffer<SoftBodyPosition> positions = m_Manager.GetBuffer<SoftBodyPosition>(body);
            positions[0] = new SoftBodyPosition { Value = new float3(float.NaN, 0f, 0f) };
            Update();

            ParticleBodyState state = m_Manager.GetComponentData<ParticleBodyState>(body);
            Assert.That(state.LastReport.Reset, Is.True, "the NaN guard fired");
            Assert.That(state.LastReport.BadParticle, Is.EqualTo(0), "and named the particle");
            Assert.That(state.Status.ResetCount, Is.EqualTo(before.ResetCount + 1));
            AssertAllFinite(Positions(body));

            Update();
            Assert.That(m_Manager.GetComponentData<ParticleBodyState>(body).LastReport.Reset, Is.False, "the reset state is healthy");
        }

        [Test]
        public void Impulse_WakesASleepingBody_AndIsConsumed()
        {
            ShapeMatchingParameters parameters = ShapeMatchingParameters.Default;
            parameters.Body.Acceleration = float3.zero;
            parameters.Body.SleepDelay = 0.1f;
            Entity body = CreateBody(float3.zero, quaternion.identity, parameters);
            Update(20);
            Assert.That(Status(body).Asleep, Is.True, "a body at rest without gravity falls asleep");
            float3 before = Status(body).Center;

            m_Manager.SetComponentData(body, new SoftBodyImpulse { LinearVelocityChange = new float3(1f, 0f, 0f) });
            m_Manager.SetComponentEnabled<SoftBodyImpulse>(body, true);
            Update();

            Assert.That(m_Manager.IsComponentEnabled<SoftBodyImpulse>(body), Is.False, "the impulse is applied once");
            ParticleBodyStatus after = Status(body);
            Assert.That(after.Asleep, Is.False, "the impulse woke the body");
            Assert.That(after.Center.x - before.x, Is.EqualTo(k_Dt).Within(1e-4f), "1 m/s for one step");
        }

        [Test]
        public void IdenticalBodies_EvolveIdentically_WhateverTheirJobOrder()
        {
            var offsets = new[] { new float3(-2f, 3f, 0f), new float3(0f, 3f, 0f), new float3(2f, 3f, 0f) };
            var bodies = new Entity[offsets.Length];
            for (int b = 0; b < bodies.Length; b++)
                bodies[b] = CreateBody(offsets[b], quaternion.AxisAngle(new float3(1f, 0f, 0f), 0.3f), ShapeMatchingParameters.Default);

            Update(20);

            float3[] reference = Positions(bodies[0]);
            for (int b = 1; b < bodies.Length; b++)
            {
                float3[] x = Positions(bodies[b]);
                for (int i = 0; i < x.Length; i++)
                    Assert.That(math.distance(x[i] - offsets[b], reference[i] - offsets[0]), Is.LessThan(1e-4f),
                        $"body {b}, particle {i}: no coupling between bodies");
            }
        }
    }
}
