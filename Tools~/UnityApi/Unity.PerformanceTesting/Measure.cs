using System;
using Unity.PerformanceTesting.Measurements;

namespace Unity.PerformanceTesting
{
    // https://docs.unity3d.com/Packages/com.unity.test-framework.performance@3.2/api/Unity.PerformanceTesting.Measure.html
    // source: Runtime/Measure.cs (3.1.0, 3.5.0)
    public static class Measure
    {
        // https://docs.unity3d.com/Packages/com.unity.test-framework.performance@3.2/api/Unity.PerformanceTesting.Measure.html#Unity_PerformanceTesting_Measure_Method_System_Action_
        public static MethodMeasurement Method(Action action) => throw null;
    }
}
