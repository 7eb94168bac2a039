using System;
using System.Collections;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Collections;
using Unity.Entities;
using Unity.Mathematics;
using Unity.Transforms;
using UnityEngine.TestTools;

namespace SoftBodyDynamics.Tests.Runtime
{
    /// <summary>
    /// The package's pipeline in Play Mode: entities made in code in the default world, stepped by the player loop
    /// (<see cref="ParticleSimulationSystemGroup"/> inside the fixed-step group), outcomes read after some seconds of
    /// simulated time. A jelly of each method comes to rest on a floor collider; a tap fills a box with the count its rate
    /// and duration give; a scene of soft bodies only never updates the fluid system, and a scene of fluid only never
    /// updates a soft-body system.
    /// </summary>
    public class ParticlePipelineTests
    {
        /// <summary>Most frames a test waits for its simulated time, whatever the frame rate.</summary>
        const int k_MaxFrames = 20000;

        World m_World;
        EntityManager m_Manager;
        readonly List<Entity> m_Entities = new List<Entity>();
        readonly List<IDisposable> m_Blobs = new List<IDisposable>();

        [SetUp]
        public void SetUp()
        {
            m_World = World.DefaultGameObjectInjectionWorld;
            Assert.That(m_World, Is.Not.Null, "Play Mode creates the default world");
            m_Manager = m_World.EntityManager;
        }

        [TearDown]
        public void TearDown()
        {
            m_Manager.CompleteAllTrackedJobs();
            foreach (Entity e in m_Entities)
                if (m_Manager.Exists(e))
                    m_Manager.DestroyEntity(e);
            m_Entities.Clear();
            foreach (IDisposable blob in m_Blobs)
                blob.Dispose();
            m_Blobs.Clear();
        }

        /// <summary>Frames until <paramref name="seconds"/> of world time have passed (at most <see cref="k_MaxFrames"/>).</summary>
        IEnumerator Run(double seconds)
        {
            double end = m_World.Time.ElapsedTime + seconds;
            for (int frame = 0; frame < k_MaxFrames && m_World.Time.ElapsedTime < end; frame++)
                yield return null;
            m_Manager.CompleteAllTrackedJobs();
        }

        Entity Track(Entity e)
        {
            m_Entities.Add(e);
            return e;
        }

        /// <summary>A 0.4 m jelly cube of 2 × 2 × 2 cells (27 nodes) centred on its mesh origin.</summary>
        static TetrahedralMesh Cube() => BoxTetrahedra.Create(new float3(0.4f), new int3(2), float3.zero);

        Entity Floor()
        {
            Entity floor = Track(m_Manager.CreateEntity());
            m_Manager.AddComponentData(floor, new ParticleCollider { Shape = ColliderShape.Plane(float3.zero, new float3(0f, 1f, 0f)) });
            return floor;
        }

        Entity Body(SoftBodyMethod method, float3 position)
        {
            TetrahedralMesh mesh = Cube();
            var issues = new List<ValidationIssue>();
            Entity e = Track(m_Manager.CreateEntity());
            m_Manager.AddComponentData(e, LocalTransform.FromPositionRotation(position, quaternion.identity));
            switch (method)
            {
                case SoftBodyMethod.ShapeMatching:
                {
                    var masses = new float[mesh.NodeCount];
                    for (int i = 0; i < masses.Length; i++)
                        masses[i] = 1f / masses.Length;
                    ClusterSet clusters = ClusterBuilder.Build(mesh.Positions, 0.4f * 1.001f);
                    ShapeMatchingModelData model = ShapeMatchingModelData.Create(mesh.Positions, masses, clusters.Offsets, clusters.Particles, false);
                    BlobAssetReference<ShapeMatchingShapeBlob> blob = ShapeMatchingShapeBlobFactory.Create(model, null, null, Allocator.Persistent);
                    m_Blobs.Add(blob);
                    SoftBodyArchetype.AddComponents(m_Manager, e, blob, ShapeMatchingParameters.Default);
                    break;
                }
                case SoftBodyMethod.MassSpring:
                {
                    MassSpringModelData model = MassSpringModelData.FromMesh(mesh, ElasticMaterial.Jelly, MassSpringBuildSettings.Default, issues, out _);
                    Assert.That(model, Is.Not.Null, string.Join("\n", issues));
                    BlobAssetReference<MassSpringShapeBlob> blob = MassSpringShapeBlobFactory.Create(model.AsModel(), Allocator.Persistent);
                    m_Blobs.Add(blob);
                    // Implicit Euler: stable at any fixed step the project sets.
                    MassSpringParameters p = MassSpringParameters.Default;
                    p.Integrator = MassSpringIntegrator.ImplicitEuler;
                    SoftBodyArchetype.AddMassSpringComponents(m_Manager, e, blob, p);
                    break;
                }
                default:
                {
                    FemModelData model = FemModelData.Create(mesh, ElasticMaterial.Jelly, default, issues);
                    Assert.That(model, Is.Not.Null, string.Join("\n", issues));
                    BlobAssetReference<FemShapeBlob> blob = FemShapeBlobFactory.Create(model.AsModel(), Allocator.Persistent);
                    m_Blobs.Add(blob);
                    SoftBodyArchetype.AddFemComponents(m_Manager, e, blob, FemParameters.Default);
                    break;
                }
            }
            return e;
        }

        Entity Fluid(out FluidParameters parameters)
        {
            parameters = FluidParameters.Default;
            parameters.DomainMin = new float3(-0.2f, 0f, -0.2f);
            parameters.DomainMax = new float3(0.2f, 0.4f, 0.2f);
            Entity fluid = Track(m_Manager.CreateEntity());
            FluidArchetype.AddComponents(m_Manager, fluid, new FluidSettings
            {
                Parameters = parameters, Budget = 2000, Color = new float4(1f), Storage = FluidStorage.Packed, Backend = FluidBackend.Cpu,
            });
            return fluid;
        }

        Entity Tap(Entity fluid, float rate, float duration)
        {
            FluidTapSettings s = FluidTapSettings.Default;
            s.Position = new float3(0f, 0.3f, 0f);
            s.Rotation = quaternion.AxisAngle(new float3(1f, 0f, 0f), math.PI / 2f);
            s.Rate = rate;
            s.Duration = duration;
            Entity tap = Track(m_Manager.CreateEntity());
            m_Manager.AddComponentData(tap, new FluidTap { Settings = s, Fluid = fluid });
            return tap;
        }

        [UnityTest]
        public IEnumerator JellyOfEachMethod_ComesToRestOnAFloor(
            [Values(SoftBodyMethod.ShapeMatching, SoftBodyMethod.MassSpring, SoftBodyMethod.Fem)] SoftBodyMethod method)
        {
            Floor();
            Entity body = Body(method, new float3(0f, 0.6f, 0f));
            yield return Run(4.0);

            DynamicBuffer<SoftBodyPosition> x = m_Manager.GetBuffer<SoftBodyPosition>(body, true);
            DynamicBuffer<SoftBodyVelocity> v = m_Manager.GetBuffer<SoftBodyVelocity>(body, true);
            ParticleBodyStatus status = m_Manager.GetComponentData<ParticleBodyState>(body).Status;
            Assert.That(x.Length, Is.EqualTo(27), "the body was placed");
            Assert.That(status.ResetCount, Is.Zero, "no NaN-guard reset");
            float lowest = float.MaxValue, fastest = 0f;
            for (int i = 0; i < x.Length; i++)
            {
                // Positions are relative to the body's origin.
                lowest = math.min(lowest, x[i].Value.y + status.Origin.y);
                fastest = math.max(fastest, math.length(v[i].Value));
            }
            // Particle radius 2 cm: at rest on the plane the bottom particles' centres sit one radius up; a contact may
            // leave them a fraction of a millimetre in, and 1 cm above would be a body held off the floor.
            Assert.That(lowest, Is.InRange(0.01f, 0.03f), "the bottom layer rests on the floor");
            Assert.That(status.Asleep || fastest < 0.02f, Is.True, $"at rest after 4 s (fastest particle {fastest} m/s)");
        }

        [UnityTest]
        public IEnumerator Tap_FillsABox_ToTheCountOfItsRateAndDuration()
        {
            Entity fluid = Fluid(out _);
            Tap(fluid, 300f, 1f);
            yield return Run(2.0);

            FluidStatus status = m_Manager.GetComponentData<FluidRuntime>(fluid).Status;
            // 300 particles/s for 1 s: the schedule carries fractions of a particle from frame to frame, so the tap spawns
            // 300, give or take the last fraction.
            Assert.That(status.Spawned, Is.InRange(299, 300));
            Assert.That(status.Killed + status.Expired + status.Invalid, Is.Zero, "no drain, no lifetime, nothing invalid");
            Assert.That(status.Count, Is.EqualTo(status.Spawned), "every particle is still in the box");
            DynamicBuffer<FluidPosition> x = m_Manager.GetBuffer<FluidPosition>(fluid, true);
            for (int i = 0; i < status.Count; i++)
                Assert.That(x[i].Value.y, Is.InRange(0f, 0.4f), $"particle {i} inside the box");
        }

        [UnityTest]
        public IEnumerator SoftBodiesOnly_RunNoFluidSystem_AndFluidOnly_RunsNoSoftBodySystem()
        {
            WorldUnmanaged world = m_World.Unmanaged;
            SystemHandle fluidSystem = world.GetExistingUnmanagedSystem<FluidSimulationSystem>();
            SystemHandle shapeMatching = world.GetExistingUnmanagedSystem<ShapeMatchingSimulationSystem>();
            SystemHandle massSpring = world.GetExistingUnmanagedSystem<MassSpringSimulationSystem>();
            SystemHandle fem = world.GetExistingUnmanagedSystem<FemSimulationSystem>();

            Floor();
            Entity body = Body(SoftBodyMethod.ShapeMatching, new float3(0f, 0.6f, 0f));
            uint fluidBefore = world.ResolveSystemStateRef(fluidSystem).LastSystemVersion;
            uint bodyBefore = world.ResolveSystemStateRef(shapeMatching).LastSystemVersion;
            yield return Run(0.5);
            Assert.That(world.ResolveSystemStateRef(shapeMatching).LastSystemVersion, Is.Not.EqualTo(bodyBefore), "the body's system ran");
            Assert.That(world.ResolveSystemStateRef(fluidSystem).LastSystemVersion, Is.EqualTo(fluidBefore), "no fluid: the fluid system never updated");

            m_Manager.DestroyEntity(body);
            Entity fluid = Fluid(out _);
            Tap(fluid, 300f, 0f);
            uint shapeMatchingBefore = world.ResolveSystemStateRef(shapeMatching).LastSystemVersion;
            uint massSpringBefore = world.ResolveSystemStateRef(massSpring).LastSystemVersion;
            uint femBefore = world.ResolveSystemStateRef(fem).LastSystemVersion;
            fluidBefore = world.ResolveSystemStateRef(fluidSystem).LastSystemVersion;
            yield return Run(0.5);
            Assert.That(world.ResolveSystemStateRef(fluidSystem).LastSystemVersion, Is.Not.EqualTo(fluidBefore), "the fluid's system ran");
            Assert.That(world.ResolveSystemStateRef(shapeMatching).LastSystemVersion, Is.EqualTo(shapeMatchingBefore), "no body: no shape-matching update");
            Assert.That(world.ResolveSystemStateRef(massSpring).LastSystemVersion, Is.EqualTo(massSpringBefore), "no mass-spring update");
            Assert.That(world.ResolveSystemStateRef(fem).LastSystemVersion, Is.EqualTo(femBefore), "no FEM update");
            Assert.That(m_Manager.GetComponentData<FluidRuntime>(fluid).Status.Count, Is.GreaterThan(0), "the tap poured");
        }
    }
}
