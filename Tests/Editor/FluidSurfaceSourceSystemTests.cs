using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Core;
using Unity.Entities;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>
    /// The renderer's sources: a CPU fluid with a <see cref="FluidSurface"/> is uploaded with its live count, look and
    /// sphere bounds; a fluid without one is not; a destroyed fluid's source goes away; each world holds its own.
    /// </summary>
    public class FluidSurfaceSourceSystemTests
    {
        const float k_Dt = 1f / 60f;

        World m_World;
        EntityManager m_Manager;
        SystemHandle m_Simulation;
        SystemHandle m_ColliderWorld;
        FluidSurfaceSourceSystem m_Sources;
        double m_ElapsedTime;

        [SetUp]
        public void SetUp()
        {
            m_World = new World("Fluid surface source tests");
            m_Manager = m_World.EntityManager;
            m_ColliderWorld = m_World.CreateSystem<ColliderWorldSystem>();
            m_Simulation = m_World.CreateSystem<FluidSimulationSystem>();
            m_Sources = m_World.GetOrCreateSystemManaged<FluidSurfaceSourceSystem>();
            m_ElapsedTime = 0.0;
        }

        [TearDown]
        public void TearDown()
        {
            m_Manager.CompleteAllTrackedJobs();
            m_World.Dispose();
        }

        Entity CreateFluid(bool surface)
        {
            FluidParameters p = FluidTestEntities.BoxParameters();
            Entity entity = FluidTestEntities.Create(m_Manager, new FluidSettings
            {
                Parameters = p, Budget = 2000, Color = new float4(1f), Storage = FluidStorage.Packed, Backend = FluidBackend.Cpu,
            });
            if (surface)
                m_Manager.AddComponentData(entity, new FluidSurface { Look = FluidLook.Honey, ParticleRadius = 0.7f * p.ParticleSpacing });
            FluidTestEntities.CreateTap(m_Manager, entity, 300f);
            return entity;
        }

        void Update(int frames)
        {
            for (int f = 0; f < frames; f++)
            {
                m_ElapsedTime += k_Dt;
                m_World.SetTime(new TimeData(m_ElapsedTime, k_Dt));
                m_ColliderWorld.Update(m_World.Unmanaged);
                m_Simulation.Update(m_World.Unmanaged);
                m_Manager.CompleteAllTrackedJobs();
                m_Sources.Update();
            }
        }

        [Test]
        public void FluidWithSurface_IsUploadedWithItsLiveCountLookAndBounds()
        {
            Entity fluid = CreateFluid(surface: true);
            Update(20);
            FluidRenderSource source = m_Sources.Sources.Get(fluid);
            Assert.That(source, Is.Not.Null);
            int live = m_Manager.GetComponentData<FluidRuntime>(fluid).Status.Count;
            Assert.That(live, Is.GreaterThan(0));
            Assert.That(source.Count, Is.EqualTo(live));
            Assert.That(source.Particles.count, Is.GreaterThanOrEqualTo(live));
            Assert.That(source.Look.Model, Is.EqualTo(FluidLook.Honey.Model));
            Assert.That(source.Look.Colour.x, Is.EqualTo(FluidLook.Honey.Colour.x));
            DynamicBuffer<FluidPosition> positions = m_Manager.GetBuffer<FluidPosition>(fluid);
            for (int i = 0; i < live; i++)
            {
                float3 p = positions[i].Value;
                Assert.That(source.WorldBounds.Contains(new Vector3(p.x, p.y, p.z)), $"particle {i} outside the bounds");
            }
        }

        [Test]
        public void FluidWithoutSurface_IsNotUploaded()
        {
            Entity fluid = CreateFluid(surface: false);
            Update(5);
            Assert.That(m_Sources.Sources.Get(fluid), Is.Null);
        }

        [Test]
        public void DestroyedFluid_LeavesTheSources()
        {
            Entity fluid = CreateFluid(surface: true);
            Entity other = CreateFluid(surface: true);
            Update(3);
            Assert.That(m_Sources.Sources.Get(fluid), Is.Not.Null);
            m_Manager.DestroyEntity(fluid);
            Update(1);
            Assert.That(m_Sources.Sources.Get(fluid), Is.Null);
            Assert.That(m_Sources.Sources.Get(other), Is.Not.Null, "the other fluid keeps being drawn");
        }

        [Test]
        public void TwoWorlds_KeepTheirOwnSources_UnderTheSameEntityKey()
        {
            Entity fluid = CreateFluid(surface: true);
            var other = new World("Fluid surface source tests, second world");
            try
            {
                EntityManager otherManager = other.EntityManager;
                SystemHandle otherColliders = other.CreateSystem<ColliderWorldSystem>();
                SystemHandle otherSimulation = other.CreateSystem<FluidSimulationSystem>();
                FluidSurfaceSourceSystem otherSources = other.GetOrCreateSystemManaged<FluidSurfaceSourceSystem>();
                FluidParameters p = FluidTestEntities.BoxParameters();
                Entity otherFluid = FluidTestEntities.Create(otherManager, new FluidSettings
                {
                    Parameters = p, Budget = 2000, Color = new float4(1f), Storage = FluidStorage.Packed, Backend = FluidBackend.Cpu,
                });
                otherManager.AddComponentData(otherFluid, new FluidSurface { Look = FluidLook.Water, ParticleRadius = 0.5f * p.ParticleSpacing });
                FluidTestEntities.CreateTap(otherManager, otherFluid, 300f);
                Assert.That(otherFluid, Is.EqualTo(fluid), "both worlds made the same entities in the same order");

                Update(3);
                other.SetTime(new TimeData(k_Dt, k_Dt));
                otherColliders.Update(other.Unmanaged);
                otherSimulation.Update(other.Unmanaged);
                otherManager.CompleteAllTrackedJobs();
                otherSources.Update();

                FluidRenderSource mine = m_Sources.Sources.Get(fluid), theirs = otherSources.Sources.Get(otherFluid);
                Assert.That(mine, Is.Not.Null);
                Assert.That(theirs, Is.Not.Null);
                Assert.That(mine, Is.Not.SameAs(theirs), "one key, two worlds, two sources");
                Assert.That(mine.ParticleRadius, Is.EqualTo(0.7f * p.ParticleSpacing), "this world's fluid");
                Assert.That(theirs.ParticleRadius, Is.EqualTo(0.5f * p.ParticleSpacing), "the other world's fluid");
                Assert.That(FluidRenderSources.Of(m_World), Is.SameAs(m_Sources.Sources));

                var all = new List<FluidRenderSource>();
                FluidRenderSources.CollectAll(all);
                Assert.That(all, Does.Contain(mine).And.Contain(theirs));
                other.Dispose();
                FluidRenderSources.CollectAll(all);
                Assert.That(all, Does.Contain(mine).And.Not.Contain(theirs), "a disposed world takes its sources with it");
            }
            finally
            {
                if (other.IsCreated)
                    other.Dispose();
            }
        }

        [Test]
        public void Pack_BoundsCoverTheSpheresAndSkipNonFinitePositions()
        {
            var positions = new Unity.Collections.NativeArray<FluidPosition>(3, Unity.Collections.Allocator.Temp);
            var attributes = new Unity.Collections.NativeArray<FluidAttribute>(3, Unity.Collections.Allocator.Temp);
            positions[0] = new FluidPosition { Value = new float3(0f, 0f, 0f) };
            positions[1] = new FluidPosition { Value = new float3(1f, 2f, 3f) };
            positions[2] = new FluidPosition { Value = new float3(float.NaN, 0f, 0f) };
            attributes[1] = new FluidAttribute { Value = 1200f };
            var packed = new Unity.Collections.NativeArray<float4>(3, Unity.Collections.Allocator.Temp);
            Bounds b = FluidSurfaceSourceSystem.Pack(positions, attributes, 3, 0.1f, packed);
            Assert.That(b.Contains(new Vector3(-0.09f, -0.09f, -0.09f)) && b.Contains(new Vector3(1.09f, 2.09f, 3.09f)));
            Assert.That(packed[1].w, Is.EqualTo(1200f));
            Assert.That(FluidSurfaceSourceSystem.GrownLength(65), Is.EqualTo(128));
            positions.Dispose();
            attributes.Dispose();
            packed.Dispose();
        }
    }
}
