using System.Collections.Generic;
using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using UnityEditor;
using UnityEditor.UIElements;
using UnityEngine;
using UnityEngine.UIElements;

namespace SoftBodyDynamics.Editor
{
    /// <summary>
    /// Inspector of <see cref="FluidTapAuthoring"/>: every setting, a read-out of the steady-state alive particles
    /// (rate × lifetime, bursts included) against the fluid's budget, and the live validation errors and warnings —
    /// an error when the tap would sustain more particles than the budget. The gizmo (cone and flow) is drawn by the
    /// component itself.
    /// </summary>
    [CustomEditor(typeof(FluidTapAuthoring))]
    [CanEditMultipleObjects]
    public sealed class FluidTapAuthoringEditor : UnityEditor.Editor
    {
        static readonly string[] s_Fields =
        {
            nameof(FluidTapAuthoring.fluid), nameof(FluidTapAuthoring.shape), nameof(FluidTapAuthoring.radius), nameof(FluidTapAuthoring.boxSize),
            nameof(FluidTapAuthoring.coneAngle), nameof(FluidTapAuthoring.speed), nameof(FluidTapAuthoring.speedRandom),
            nameof(FluidTapAuthoring.rateMode), nameof(FluidTapAuthoring.rate), nameof(FluidTapAuthoring.volumeFlow),
            nameof(FluidTapAuthoring.bursts), nameof(FluidTapAuthoring.pulsePeriod), nameof(FluidTapAuthoring.pulseDutyCycle),
            nameof(FluidTapAuthoring.duration), nameof(FluidTapAuthoring.looping), nameof(FluidTapAuthoring.startDelay),
            nameof(FluidTapAuthoring.prewarm), nameof(FluidTapAuthoring.maxAlive), nameof(FluidTapAuthoring.lifetime),
            nameof(FluidTapAuthoring.lifetimeRandom), nameof(FluidTapAuthoring.attribute), nameof(FluidTapAuthoring.seed),
        };

        VisualElement m_Readout;

        public override VisualElement CreateInspectorGUI()
        {
            var root = new VisualElement();
            m_Readout = new VisualElement();
            root.Add(m_Readout);
            foreach (string field in s_Fields)
                root.Add(new PropertyField(serializedObject.FindProperty(field)));
            InspectorSupport.TrackTargetsAndTransforms(root, this, Refresh);
            Refresh();
            return root;
        }

        void Refresh()
        {
            if (m_Readout == null)
                return;
            m_Readout.Clear();
            bool several = targets.Length > 1;
            foreach (Object selected in targets)
            {
                var tap = selected as FluidTapAuthoring;
                if (tap == null)
                    continue;
                string prefix = several ? tap.name + ": " : "";
                if (tap.fluid == null)
                {
                    m_Readout.Add(InspectorSupport.IssueBox(prefix + "Assign the Fluid this tap pours into.", IssueSeverity.Error));
                    continue;
                }
                double alive = tap.SteadyStateAlive();
                string readout = double.IsInfinity(alive)
                    ? $"{prefix}Steady state: unbounded (particles live forever); budget {tap.fluid.particleBudget}."
                    : $"{prefix}Steady state: about {alive:0} alive particles (rate × lifetime); budget {tap.fluid.particleBudget}.";
                m_Readout.Add(new HelpBox(readout, HelpBoxMessageType.Info));
                var issues = new List<ValidationIssue>();
                FluidValidation.ValidateTap(tap.ToSettings(), tap.bursts ?? new FluidTapBurst[0], tap.fluid.particleSpacing, tap.fluid.particleBudget, issues);
                foreach (ValidationIssue issue in issues)
                    m_Readout.Add(InspectorSupport.IssueBox(prefix + issue.Message, issue.Severity));
            }
        }
    }
}
