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

        // ...Measure.html#Unity_PerformanceTesting_Measure_Custom_Unity_PerformanceTesting_SampleGroup_System_Double_
        // https://github.com/needle-mirror/com.unity.test-framework.performance/blob/3.1.0/Runtime/Measure.cs (same in 3.5.0;
        // throws on NaN)
        public static void Custom(SampleGroup sampleGroup, double value) => throw null;

        // ...Measure.html#Unity_PerformanceTesting_Measure_Custom_System_String_System_Double_
        // https://github.com/needle-mirror/com.unity.test-framework.performance/blob/3.1.0/Runtime/Measure.cs (same in 3.5.0)
        public static void Custom(string name, double value) => throw null;
    }
}
