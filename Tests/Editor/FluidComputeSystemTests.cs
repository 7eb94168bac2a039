using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Core;
using Unity.Entities;
using Unity.Mathematics;
using UnityEditor;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>
    /// The GPU fluid system in a test world next to the CPU one: a fluid that asks for the CPU, or cannot run on the GPU,
    /// stays with the CPU system; one that can is taken by the GPU system, fills from its tap on the GPU and comes back
    /// into its buffers through the read-back.
    /// </summary>
    public class FluidComputeSystemTests
    {
        const float k_Dt = 1f / 60f;
        const string k_ShaderPath = "Packages/com.softbodydynamics.dots/Shaders/FluidSolver.compute";

        World m_World;
        EntityManager m_Manager;
        SystemHandle m_Simulation;
        SystemHandle m_ColliderWorld;
        FluidComputeSystem m_Compute;
        double m_ElapsedTime;

        [SetUp]
        public void SetUp()
        {
            m_World = new World("Fluid compute system tests");
            m_Manager = m_World.EntityManager;
            m_ColliderWorld = m_World.CreateSystem<ColliderWorldSystem>();
            m_Compute = m_World.GetOrCreateSystemManaged<FluidComputeSystem>();
            m_Simulation = m_World.CreateSystem<FluidSimulationSystem>();
            m_ElapsedTime = 0.0;
        }

        [TearDown]
        public void TearDown()
        {
            m_Manager.CompleteAllTrackedJobs();
            m_World.Dispose();
        }

        Entity CreateFluid(FluidBackend backend, ComputeShader shader, FluidReadback readback)
        {
            Entity entity = FluidTestEntities.Create(m_Manager, new FluidSettings
            {
                Parameters = FluidTestEntities.BoxParameters(), Budget = 2000, Color = new float4(1f), Storage = FluidStorage.Packed, Backend = backend, Readback = readback,
                ReadbackInterval = 1,
            });
            m_Manager.AddComponentData(entity, new FluidComputeShader { Shader = shader });
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
                m_Compute.Update();
                m_Simulation.Update(m_World.Unmanaged);
                m_Manager.CompleteAllTrackedJobs();
                AsyncGPUReadback.WaitAllRequests();
            }
        }

        FluidStatus Status(Entity fluid) => m_Manager.GetComponentData<FluidRuntime>(fluid).Status;

        [Test]
        public void CpuBackend_StaysWithTheCpuSystem()
        {
            Entity fluid = CreateFluid(FluidBackend.Cpu, null, FluidReadback.Never);
            Update(20);
            Assert.That(m_Manager.HasComponent<FluidOnGpu>(fluid), Is.False);
            Assert.That(Status(fluid).Count, Is.GreaterThan(0), "the CPU system stepped the fluid and its tap");
        }

        [Test]
        public void AutoWithoutComputeShader_FallsBackToTheCpuSystem()
        {
            Entity fluid = CreateFluid(FluidBackend.Auto, null, FluidReadback.Never);
            Update(20);
            Assert.That(m_Manager.HasComponent<FluidOnGpu>(fluid), Is.False);
            Assert.That(Status(fluid).Count, Is.GreaterThan(0));
        }

        [Test]
        public void GpuBackend_FillsOnTheGpuAndReadsBack()
        {
            if (!SystemInfo.supportsComputeShaders || !SystemInfo.supportsAsyncGPUReadback)
                Assert.Ignore("This device runs no compute shaders or asynchronous read-backs.");
            var shader = (ComputeShader)AssetDatabase.LoadAssetAtPath(k_ShaderPath, typeof(ComputeShader));
            Assert.That(shader, Is.Not.Null, k_ShaderPath);
            Entity fluid = CreateFluid(FluidBackend.Gpu, shader, FluidReadback.EveryFrame);
            Update(40);
            Assert.That(m_Manager.HasComponent<FluidOnGpu>(fluid), Is.True, "the GPU system took the fluid");
            FluidStatus status = Status(fluid);
            Assert.That(status.Count, Is.GreaterThan(100), "the tap filled the fluid on the GPU");
            Assert.That(status.Count, Is.EqualTo(status.Spawned - status.Killed - status.Expired - status.Invalid).Within(300 * k_Dt * 3),
                "the count identity, up to the spawns of the frames whose read-back is still in flight");
            DynamicBuffer<FluidPosition> positions = m_Manager.GetBuffer<FluidPosition>(fluid);
            for (int i = 0; i < math.min(status.Count, positions.Length); i++)
                Assert.That(math.all(positions[i].Value >= new float3(-0.2f, 0f, -0.2f)) && math.all(positions[i].Value <= new float3(0.2f, 0.4f, 0.2f)), Is.True,
                    $"particle {i} read back at {positions[i].Value}");
        }
    }
}
