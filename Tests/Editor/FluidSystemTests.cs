using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Core;
using Unity.Entities;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>
    /// The fluid system in a test world: it runs only when a fluid exists, a tap fills the fluid's packed buffers, a
    /// drain empties them, and the count obeys Count = Spawned − Killed − Expired − Invalid. Each update steps the
    /// system once with a fixed dt and completes the jobs.
    /// </summary>
    public class FluidSystemTests
    {
        const float k_Dt = 1f / 60f;

        World m_World;
        EntityManager m_Manager;
        SystemHandle m_Simulation;
        SystemHandle m_ColliderWorld;
        double m_ElapsedTime;

        [SetUp]
        public void SetUp()
        {
            m_World = new World("Fluid system tests");
            m_Manager = m_World.EntityManager;
            m_ColliderWorld = m_World.CreateSystem<ColliderWorldSystem>();
            m_Simulation = m_World.CreateSystem<FluidSimulationSystem>();
            m_ElapsedTime = 0.0;
        }

        [TearDown]
        public void TearDown()
        {
            m_Manager.CompleteAllTrackedJobs();
            m_World.Dispose();
        }

        /// <summary>A water fluid in a 0.4 m box above the origin, with the components the baker adds.</summary>
        Entity CreateFluid(int budget) => CreateFluid(budget, FluidStorage.Packed, Entity.Null);

        Entity CreateFluid(int budget, FluidStorage storage, Entity prefab) =>
            FluidTestEntities.Create(m_Manager, new FluidSettings
            {
                Parameters = FluidTestEntities.BoxParameters(), Budget = budget, Color = new float4(1f), Storage = storage, ParticlePrefab = prefab,
            });

        Entity CreateTap(Entity fluid, float rate, float lifetime) => FluidTestEntities.CreateTap(m_Manager, fluid, rate, lifetime);

        void Update(int frames = 1)
        {
            for (int f = 0; f < frames; f++)
            {
                m_ElapsedTime += k_Dt;
                m_World.SetTime(new TimeData(m_ElapsedTime, k_Dt));
                m_ColliderWorld.Update(m_World.Unmanaged);
                m_Simulation.Update(m_World.Unmanaged);
                m_Manager.CompleteAllTrackedJobs();
            }
        }

        FluidStatus Status(Entity fluid) => m_Manager.GetComponentData<FluidRuntime>(fluid).Status;

        [Test]
        public void FluidSystem_RunsOnlyWhenAFluidExists()
        {
            Assert.That(m_World.Unmanaged.ResolveSystemStateRef(m_Simulation).ShouldRunSystem(), Is.False, "no fluid: no fluid system");
            Assert.That(m_World.Unmanaged.ResolveSystemStateRef(m_ColliderWorld).ShouldRunSystem(), Is.False, "nor a collider world");
            CreateFluid(100);
            Assert.That(m_World.Unmanaged.ResolveSystemStateRef(m_Simulation).ShouldRunSystem(), Is.True);
            Assert.That(m_World.Unmanaged.ResolveSystemStateRef(m_ColliderWorld).ShouldRunSystem(), Is.True, "a fluid reads the collider world");
        }

        [Test]
        public void WorldSettings_GiveTheFluidTheirGravityAndMinimumSubsteps()
        {
            Entity fluid = CreateFluid(2000);
            CreateTap(fluid, 300f, 0f);
            Update(2);
            int alone = m_Manager.GetComponentData<FluidRuntime>(fluid).LastFrame.Step.Substeps;
            Entity world = m_Manager.CreateEntity();
            m_Manager.AddComponentData(world, new ParticleWorldSettings { Gravity = float3.zero, MinSubsteps = alone + 3 });
            Update(10);
            Assert.That(m_Manager.GetComponentData<FluidRuntime>(fluid).LastFrame.Step.Substeps, Is.EqualTo(alone + 3), "the world's minimum substeps");
            // Without gravity the poured particles keep the tap's 1 m/s downward, give or take the pressure between them.
            DynamicBuffer<FluidVelocity> v = m_Manager.GetBuffer<FluidVelocity>(fluid, true);
            FluidStatus status = Status(fluid);
            float fastest = 0f;
            for (int i = 0; i < status.Count; i++)
                fastest = math.max(fastest, math.length(v[i].Value));
            Assert.That(fastest, Is.LessThan(1.5f), "under Earth gravity the oldest particles, 12 frames out of the tap, would move at 2.96 m/s");
        }

        [Test]
        public void Tap_FillsThePackedBuffers_AndParticlesFall()
        {
            Entity fluid = CreateFluid(2000);
            CreateTap(fluid, 300f, 0f);
            Update(30);
            FluidStatus status = Status(fluid);
            Assert.That(status.Count, Is.GreaterThan(50));
            Assert.AreEqual(2000, m_Manager.GetBuffer<FluidPosition>(fluid, true).Length, "buffers sized to the budget");
            DynamicBuffer<FluidPosition> x = m_Manager.GetBuffer<FluidPosition>(fluid, true);
            for (int i = 0; i < status.Count; i++)
            {
                Assert.That(math.all(math.isfinite(x[i].Value)));
                Assert.That(x[i].Value.y, Is.LessThanOrEqualTo(0.3f + 1e-3f), "poured down from the tap");
            }
            Assert.AreEqual(status.Spawned - status.Killed - status.Expired - status.Invalid, status.Count);
        }

        [Test]
        public void Drain_AndLifetimes_RemoveParticles_AndTheCountAddsUp()
        {
            Entity fluid = CreateFluid(2000);
            CreateTap(fluid, 300f, 0.5f);
            Entity drain = m_Manager.CreateEntity();
            m_Manager.AddComponentData(drain, new FluidDrainVolume
            {
                Drain = new FluidDrain { Shape = ColliderShape.Box(new float3(0f, 0.02f, 0f), quaternion.identity, new float3(0.2f, 0.03f, 0.2f)) },
                Fluid = fluid,
            });
            Update(90);
            FluidStatus status = Status(fluid);
            Assert.That(status.Killed + status.Expired, Is.GreaterThan(0));
            Assert.AreEqual(status.Spawned - status.Killed - status.Expired - status.Invalid, status.Count);
        }

        /// <summary>Particle entities of <paramref name="fluid"/> (Entities storage).</summary>
        int ParticleEntities(Entity fluid)
        {
            EntityQuery query = m_Manager.CreateEntityQuery(typeof(FluidParticle));
            var data = query.ToComponentDataArray<FluidParticle>(Unity.Collections.Allocator.Temp);
            int n = 0;
            for (int i = 0; i < data.Length; i++)
                n += data[i].Fluid == fluid ? 1 : 0;
            data.Dispose();
            return n;
        }

        [Test]
        public void EntityStorage_HasOneEntityPerParticle_AndGameplayCanDestroyOne()
        {
            // The template the particles are instantiated from: a FluidParticle of no fluid and a transform.
            Entity template = m_Manager.CreateEntity();
            m_Manager.AddComponentData(template, new FluidParticle());
            m_Manager.AddComponentData(template, Unity.Transforms.LocalTransform.FromPositionRotation(float3.zero, quaternion.identity));
            Entity fluid = CreateFluid(2000, FluidStorage.Entities, template);
            CreateTap(fluid, 300f, 0f);
            Update(20);
            FluidStatus status = Status(fluid);
            Assert.That(status.Count, Is.GreaterThan(20));
            Assert.AreEqual(status.Count, ParticleEntities(fluid), "one entity per live particle");

            // Gameplay destroys one particle entity: it leaves the fluid and counts as killed.
            EntityQuery query = m_Manager.CreateEntityQuery(typeof(FluidParticle));
            var entities = query.ToEntityArray(Unity.Collections.Allocator.Temp);
            var data = query.ToComponentDataArray<FluidParticle>(Unity.Collections.Allocator.Temp);
            for (int i = 0; i < entities.Length; i++)
                if (data[i].Fluid == fluid)
                {
                    m_Manager.DestroyEntity(entities[i]);
                    break;
                }
            entities.Dispose();
            data.Dispose();
            long killed = Status(fluid).Killed;
            Update(1);
            status = Status(fluid);
            Assert.That(status.Killed, Is.GreaterThanOrEqualTo(killed + 1));
            Assert.AreEqual(status.Count, ParticleEntities(fluid));
            Assert.AreEqual(status.Spawned - status.Killed - status.Expired - status.Invalid, status.Count);
        }
    }
}
