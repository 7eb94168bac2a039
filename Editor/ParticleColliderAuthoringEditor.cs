using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using UnityEditor;
using UnityEditor.UIElements;
using UnityEngine;
using UnityEngine.UIElements;

namespace SoftBodyDynamics.Editor
{
    /// <summary>
    /// Inspector of <see cref="ParticleColliderAuthoring"/>: shows only the size fields the chosen shape uses and
    /// the live list of validation errors and warnings, including those caused by the Transform's scale.
    /// </summary>
    [CustomEditor(typeof(ParticleColliderAuthoring))]
    [CanEditMultipleObjects]
    public sealed class ParticleColliderAuthoringEditor : UnityEditor.Editor
    {
        PropertyField m_Size;
        PropertyField m_Radius;
        PropertyField m_Height;
        PropertyField m_Direction;
        VisualElement m_Issues;

        public override VisualElement CreateInspectorGUI()
        {
            var root = new VisualElement();
            m_Issues = new VisualElement();
            root.Add(m_Issues);
            root.Add(new PropertyField(serializedObject.FindProperty(nameof(ParticleColliderAuthoring.shape))));
            root.Add(new PropertyField(serializedObject.FindProperty(nameof(ParticleColliderAuthoring.center))));
            root.Add(m_Size = new PropertyField(serializedObject.FindProperty(nameof(ParticleColliderAuthoring.size))));
            root.Add(m_Radius = new PropertyField(serializedObject.FindProperty(nameof(ParticleColliderAuthoring.radius))));
            root.Add(m_Height = new PropertyField(serializedObject.FindProperty(nameof(ParticleColliderAuthoring.height))));
            root.Add(m_Direction = new PropertyField(serializedObject.FindProperty(nameof(ParticleColliderAuthoring.direction))));

            InspectorSupport.TrackTargetsAndTransforms(root, this, Refresh);
            Refresh();
            return root;
        }

        void Refresh()
        {
            if (m_Issues == null)
                return;
            bool usesSize = false, usesRadius = false, usesCapsule = false;
            bool several = targets.Length > 1;
            m_Issues.Clear();
            foreach (Object selected in targets)
            {
                var collider = selected as ParticleColliderAuthoring;
                if (collider == null)
                    continue;
                usesSize |= collider.shape == ColliderShapeType.Box;
                usesRadius |= collider.shape == ColliderShapeType.Sphere || collider.shape == ColliderShapeType.Capsule;
                usesCapsule |= collider.shape == ColliderShapeType.Capsule;
                string prefix = several ? collider.name + ": " : "";
                foreach (ValidationIssue issue in ParticleColliderValidation.Validate(collider))
                    m_Issues.Add(InspectorSupport.IssueBox(prefix + issue.Message, issue.Severity));
            }
            Show(m_Size, usesSize);
            Show(m_Radius, usesRadius);
            Show(m_Height, usesCapsule);
            Show(m_Direction, usesCapsule);
        }

        static void Show(VisualElement element, bool visible) =>
            element.style.display = new StyleEnum<DisplayStyle>(visible ? DisplayStyle.Flex : DisplayStyle.None);
    }
}
