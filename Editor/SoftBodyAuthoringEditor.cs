using System;
using System.Collections.Generic;
using System.Text;
using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using UnityEditor;
using UnityEditor.UIElements;
using UnityEngine.UIElements;

namespace SoftBodyDynamics.Editor
{
    /// <summary>
    /// Inspector of <see cref="SoftBodyAuthoring"/>: the method, the counts the current settings give (particles and
    /// clusters; or nodes, tetrahedra, springs and the explicit stable step), the live list of validation errors and
    /// warnings (the same checks the baker runs), preset buttons, and the fields grouped in foldouts. Fields that only one
    /// method uses are shown only while a selected body uses that method.
    /// </summary>
    [CustomEditor(typeof(SoftBodyAuthoring))]
    [CanEditMultipleObjects]
    public sealed class SoftBodyAuthoringEditor : UnityEditor.Editor
    {
        static readonly SoftBodyPreset[] k_PresetButtons = { SoftBodyPreset.Jelly, SoftBodyPreset.Rubber, SoftBodyPreset.Clay };

        Label m_Counts;
        VisualElement m_Issues;
        readonly List<VisualElement> m_ShapeMatchingOnly = new List<VisualElement>();
        readonly List<VisualElement> m_TetrahedralOnly = new List<VisualElement>();
        readonly List<VisualElement> m_MassSpringOnly = new List<VisualElement>();
        readonly List<VisualElement> m_FemOnly = new List<VisualElement>();

        public override VisualElement CreateInspectorGUI()
        {
            var root = new VisualElement();
            m_ShapeMatchingOnly.Clear();
            m_TetrahedralOnly.Clear();
            m_MassSpringOnly.Clear();
            m_FemOnly.Clear();
            m_Counts = new Label();
            root.Add(m_Counts);
            m_Issues = new VisualElement();
            root.Add(m_Issues);

            AddFields(root, nameof(SoftBodyAuthoring.method));

            Foldout shape = Section("Shape");
            m_ShapeMatchingOnly.AddRange(AddFields(shape, nameof(SoftBodyAuthoring.clusterSize),
                nameof(SoftBodyAuthoring.addInteriorParticles), nameof(SoftBodyAuthoring.interiorSpacing)));
            AddFields(shape, nameof(SoftBodyAuthoring.weldTolerance), nameof(SoftBodyAuthoring.weldDistance));
            m_ShapeMatchingOnly.AddRange(AddFields(shape, nameof(SoftBodyAuthoring.totalMass)));
            m_TetrahedralOnly.AddRange(AddFields(shape, nameof(SoftBodyAuthoring.tetResolution)));
            root.Add(shape);

            Foldout material = Section("Material / Preset", nameof(SoftBodyAuthoring.preset));
            material.Add(PresetButtons());
            m_TetrahedralOnly.AddRange(AddFields(material,
                nameof(SoftBodyAuthoring.youngsModulus), nameof(SoftBodyAuthoring.poissonRatio), nameof(SoftBodyAuthoring.density),
                nameof(SoftBodyAuthoring.materialDampingRatio)));
            m_ShapeMatchingOnly.AddRange(AddFields(material,
                nameof(SoftBodyAuthoring.mode), nameof(SoftBodyAuthoring.frequency), nameof(SoftBodyAuthoring.dampingRatio),
                nameof(SoftBodyAuthoring.beta)));
            AddFields(material, nameof(SoftBodyAuthoring.substeps));
            m_ShapeMatchingOnly.AddRange(AddFields(material, nameof(SoftBodyAuthoring.maxSubstepPhase)));
            AddFields(material, nameof(SoftBodyAuthoring.gravity));
            root.Add(material);

            Foldout massSpring = Section("Mass Spring", nameof(SoftBodyAuthoring.massSpringIntegrator), nameof(SoftBodyAuthoring.bendingSprings));
            m_MassSpringOnly.Add(massSpring);
            root.Add(massSpring);
            Foldout fem = Section("FEM", nameof(SoftBodyAuthoring.femModel), nameof(SoftBodyAuthoring.femIntegrator));
            m_FemOnly.Add(fem);
            root.Add(fem);

            Foldout plasticity = Section("Plasticity",
                nameof(SoftBodyAuthoring.plasticYield), nameof(SoftBodyAuthoring.plasticCreep),
                nameof(SoftBodyAuthoring.plasticMaxDeformation));
            m_ShapeMatchingOnly.Add(plasticity);
            root.Add(plasticity);
            root.Add(Section("Collisions",
                nameof(SoftBodyAuthoring.particleRadius), nameof(SoftBodyAuthoring.friction), nameof(SoftBodyAuthoring.restitution),
                nameof(SoftBodyAuthoring.maxDepenetrationSpeed)));
            root.Add(Section("Sleep", nameof(SoftBodyAuthoring.sleepSpeed), nameof(SoftBodyAuthoring.sleepDelay)));
            Foldout limits = Section("Limits", nameof(SoftBodyAuthoring.maxParticles), nameof(SoftBodyAuthoring.maxSpeed));
            m_ShapeMatchingOnly.AddRange(AddFields(limits, nameof(SoftBodyAuthoring.rotationIterations)));
            root.Add(limits);

            InspectorSupport.TrackTargetsAndTransforms(root, this, Refresh);
            Refresh();
            return root;
        }

        Foldout Section(string title, params string[] fields)
        {
            var foldout = new Foldout { text = title, value = true };
            AddFields(foldout, fields);
            return foldout;
        }

        List<VisualElement> AddFields(VisualElement parent, params string[] fields)
        {
            var added = new List<VisualElement>();
            foreach (string field in fields)
            {
                var element = new PropertyField(serializedObject.FindProperty(field));
                parent.Add(element);
                added.Add(element);
            }
            return added;
        }

        /// <summary>Shows the fields of the methods the selected bodies use, hides the others.</summary>
        void ShowMethodFields(bool shapeMatching, bool massSpring, bool fem)
        {
            foreach (VisualElement e in m_ShapeMatchingOnly)
                Show(e, shapeMatching);
            foreach (VisualElement e in m_TetrahedralOnly)
                Show(e, massSpring || fem);
            foreach (VisualElement e in m_MassSpringOnly)
                Show(e, massSpring);
            foreach (VisualElement e in m_FemOnly)
                Show(e, fem);
        }

        static void Show(VisualElement element, bool visible) =>
            element.style.display = new StyleEnum<DisplayStyle>(visible ? DisplayStyle.Flex : DisplayStyle.None);

        VisualElement PresetButtons()
        {
            var row = new VisualElement();
            row.style.flexDirection = new StyleEnum<FlexDirection>(FlexDirection.Row);
            foreach (SoftBodyPreset preset in k_PresetButtons)
            {
                SoftBodyPreset chosen = preset;
                var button = new Button(() => ApplyPreset(chosen))
                {
                    text = chosen.ToString(),
                    tooltip = $"Set the material values of the {chosen} preset (undoable).",
                };
                button.style.flexGrow = new StyleFloat(1f);
                row.Add(button);
            }
            return row;
        }

        void ApplyPreset(SoftBodyPreset preset)
        {
            Undo.RecordObjects(targets, $"Apply {preset} Soft Body Preset");
            foreach (UnityEngine.Object selected in targets)
            {
                var authoring = (SoftBodyAuthoring)selected;
                authoring.ApplyPreset(preset);
                PrefabUtility.RecordPrefabInstancePropertyModifications(authoring);
            }
            serializedObject.Update();
            Refresh();
        }

        /// <summary>Re-runs validation (with cached builds) for every selected body and redraws counts and issues.</summary>
        void Refresh()
        {
            if (m_Counts == null)
                return;
            m_Issues.Clear();
            var counts = new StringBuilder();
            bool several = targets.Length > 1;
            bool shapeMatching = false, massSpring = false, fem = false;
            foreach (UnityEngine.Object selected in targets)
            {
                var authoring = selected as SoftBodyAuthoring;
                if (authoring == null)
                    continue;
                shapeMatching |= authoring.method == SoftBodyMethod.ShapeMatching;
                massSpring |= authoring.method == SoftBodyMethod.MassSpring;
                fem |= authoring.method == SoftBodyMethod.Fem;
                SoftBodyAuthoringBuild report = SoftBodyAuthoringValidation.ValidateAndBuild(authoring, SoftBodyBuildPreviewCache.Build,
                    SoftBodyTetrahedralPreviewCache.Build);
                string prefix = several ? authoring.name + ": " : "";
                if (counts.Length > 0)
                    counts.Append('\n');
                counts.Append(prefix).Append(report.Method == SoftBodyMethod.ShapeMatching ? Describe(report.Result) : Describe(report.Tetrahedral));
                foreach (ValidationIssue issue in report.Issues)
                    m_Issues.Add(InspectorSupport.IssueBox(prefix + issue.Message, issue.Severity));
            }
            m_Counts.text = counts.ToString();
            ShowMethodFields(shapeMatching, massSpring, fem);
        }

        static string Describe(TetrahedralBodyBuild build)
        {
            if (build == null || !build.Succeeded)
                return "Not built: fix the errors below.";
            string elements = build.Method == SoftBodyMethod.MassSpring ? $"{build.SpringCount} springs" : "linear elements";
            return FormattableString.Invariant(
                $"{build.NodeCount} nodes, {build.TetrahedronCount} tetrahedra, {elements}; explicit integrators are stable below a substep of {build.MaxStableStep * 1000.0:0.###} ms.");
        }

        static string Describe(SoftBodyBuildResult result)
        {
            if (result == null || !result.Succeeded)
                return "Not built: fix the errors below.";
            return $"{result.ParticleCount} particles ({result.SurfaceParticleCount} surface, {result.InteriorParticleCount} interior), "
                   + $"{result.ClusterCount} clusters of {result.MeanClusterSize:0.#} particles on average.";
        }
    }
}
