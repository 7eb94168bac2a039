using System.Text;
using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using UnityEditor;
using UnityEditor.UIElements;
using UnityEngine.UIElements;

namespace SoftBodyDynamics.Editor
{
    /// <summary>
    /// Inspector of <see cref="SoftBodyAuthoring"/>: the particle and cluster counts the current settings give, the
    /// live list of validation errors and warnings (the same checks the baker runs), preset buttons, and every
    /// field grouped in foldouts.
    /// </summary>
    [CustomEditor(typeof(SoftBodyAuthoring))]
    [CanEditMultipleObjects]
    public sealed class SoftBodyAuthoringEditor : UnityEditor.Editor
    {
        static readonly SoftBodyPreset[] k_PresetButtons = { SoftBodyPreset.Jelly, SoftBodyPreset.Rubber, SoftBodyPreset.Clay };

        Label m_Counts;
        VisualElement m_Issues;

        public override VisualElement CreateInspectorGUI()
        {
            var root = new VisualElement();
            m_Counts = new Label();
            root.Add(m_Counts);
            m_Issues = new VisualElement();
            root.Add(m_Issues);

            root.Add(Section("Shape",
                nameof(SoftBodyAuthoring.clusterSize), nameof(SoftBodyAuthoring.addInteriorParticles),
                nameof(SoftBodyAuthoring.interiorSpacing), nameof(SoftBodyAuthoring.weldTolerance),
                nameof(SoftBodyAuthoring.weldDistance), nameof(SoftBodyAuthoring.totalMass)));

            Foldout material = Section("Material / Preset", nameof(SoftBodyAuthoring.preset));
            material.Add(PresetButtons());
            AddFields(material,
                nameof(SoftBodyAuthoring.mode), nameof(SoftBodyAuthoring.frequency), nameof(SoftBodyAuthoring.dampingRatio),
                nameof(SoftBodyAuthoring.beta), nameof(SoftBodyAuthoring.substeps), nameof(SoftBodyAuthoring.maxSubstepPhase),
                nameof(SoftBodyAuthoring.gravity));
            root.Add(material);

            root.Add(Section("Plasticity",
                nameof(SoftBodyAuthoring.plasticYield), nameof(SoftBodyAuthoring.plasticCreep),
                nameof(SoftBodyAuthoring.plasticMaxDeformation)));
            root.Add(Section("Collisions",
                nameof(SoftBodyAuthoring.particleRadius), nameof(SoftBodyAuthoring.friction), nameof(SoftBodyAuthoring.restitution),
                nameof(SoftBodyAuthoring.maxDepenetrationSpeed)));
            root.Add(Section("Sleep", nameof(SoftBodyAuthoring.sleepSpeed), nameof(SoftBodyAuthoring.sleepDelay)));
            root.Add(Section("Limits",
                nameof(SoftBodyAuthoring.maxParticles), nameof(SoftBodyAuthoring.maxSpeed), nameof(SoftBodyAuthoring.rotationIterations)));

            SoftBodyInspectorSupport.TrackTargetsAndTransforms(root, this, Refresh);
            Refresh();
            return root;
        }

        Foldout Section(string title, params string[] fields)
        {
            var foldout = new Foldout { text = title, value = true };
            AddFields(foldout, fields);
            return foldout;
        }

        void AddFields(VisualElement parent, params string[] fields)
        {
            foreach (string field in fields)
                parent.Add(new PropertyField(serializedObject.FindProperty(field)));
        }

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
            foreach (UnityEngine.Object selected in targets)
            {
                var authoring = selected as SoftBodyAuthoring;
                if (authoring == null)
                    continue;
                SoftBodyAuthoringBuild report = SoftBodyAuthoringValidation.ValidateAndBuild(authoring, SoftBodyBuildPreviewCache.Build);
                string prefix = several ? authoring.name + ": " : "";
                if (counts.Length > 0)
                    counts.Append('\n');
                counts.Append(prefix).Append(Describe(report.Result));
                foreach (SoftBodyIssue issue in report.Issues)
                    m_Issues.Add(SoftBodyInspectorSupport.IssueBox(prefix + issue.Message, issue.Severity));
            }
            m_Counts.text = counts.ToString();
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
