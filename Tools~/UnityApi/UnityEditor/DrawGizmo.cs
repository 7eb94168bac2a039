using System;

namespace UnityEditor
{
    // https://docs.unity3d.com/ScriptReference/DrawGizmo.html
    [AttributeUsage(AttributeTargets.Method)]
    public sealed class DrawGizmo : Attribute
    {
        // https://docs.unity3d.com/ScriptReference/DrawGizmo-ctor.html
        public DrawGizmo(GizmoType gizmo) => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/GizmoType.html (values UNCONFIRMED; names from the page)
    [Flags]
    public enum GizmoType
    {
        Pickable = 1,
        NotInSelectionHierarchy = 2,
        NonSelected = 32,
        Selected = 4,
        Active = 8,
        InSelectionHierarchy = 16,
    }
}
