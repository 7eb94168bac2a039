using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using UnityEditor;
using UnityEditor.UIElements;
using UnityEngine;
using UnityEngine.UIElements;

namespace SoftBodyDynamics.Editor
{
    /// <summary>What the soft-body and collider inspectors share: live refresh and issue help boxes.</summary>
    static class InspectorSupport
    {
        /// <summary>
        /// Calls <paramref name="refresh"/> whenever a serialized value of <paramref name="editor"/>'s targets or of
        /// their Transforms changes: both components bake the Transform (a body's scale into its rest shape, a
        /// collider's pose and scale into its world shape), so its edits change the issues too.
        /// </summary>
        public static void TrackTargetsAndTransforms(VisualElement root, UnityEditor.Editor editor, Action refresh)
        {
            root.TrackSerializedObjectValue(editor.serializedObject, _ => refresh());
            var transforms = new List<UnityEngine.Object>();
            foreach (UnityEngine.Object selected in editor.targets)
                if (selected is Component component)
                    transforms.Add(component.transform);
            root.TrackSerializedObjectValue(new SerializedObject(transforms.ToArray()), _ => refresh());
        }

        /// <summary>A help box showing <paramref name="message"/> as an error or a warning.</summary>
        public static HelpBox IssueBox(string message, IssueSeverity severity) =>
            new HelpBox(message, severity == IssueSeverity.Error ? HelpBoxMessageType.Error : HelpBoxMessageType.Warning);
    }
}
