using System.Collections.Generic;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// One point of the method study: a scene at a resolution, a method and a knob value. Step advances the body by one frame of the
    /// scene (timed: one item = one particle through a 1/60 s step, all substeps and iterations included); Evaluate
    /// runs the scene's measurement on fresh bodies of the same method and knob.
    /// </summary>
    public sealed class MethodStudyScenario : IScenario
    {
        readonly StudyScene m_Scene;
        readonly MethodVariant m_Variant;
        readonly int m_Knob, m_Resolution;
        IMethodBody m_Body;
        int m_Frame;

        public MethodStudyScenario(StudyScene scene, MethodVariant variant, int knob, int resolution = 0)
        {
            m_Scene = scene;
            m_Variant = variant;
            m_Knob = knob;
            m_Resolution = resolution;
        }

        public string Name => m_Scene.Name;
        public string Method => m_Variant.Label(m_Knob, m_Resolution);
        public int Size => m_Scene.SetupAt(m_Resolution).Mesh.NodeCount;
        public string SizeUnit => "particles";
        public long ItemsPerStep => Size;

        public void Setup()
        {
            m_Body = m_Variant.Create(m_Scene.SetupAt(m_Resolution), m_Knob, m_Scene.CellSizeAt(m_Resolution));
            m_Frame = 0;
        }

        public void Step() => m_Scene.TimedFrame(m_Body, m_Frame++);

        public IReadOnlyList<Metric> Evaluate() => m_Scene.Measure(m_Scene.SetupAt(m_Resolution), s => m_Variant.Create(s, m_Knob, m_Scene.CellSizeAt(m_Resolution)));
    }
}
