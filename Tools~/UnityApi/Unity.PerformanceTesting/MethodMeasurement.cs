using System;

namespace Unity.PerformanceTesting.Measurements
{
    // https://docs.unity3d.com/Packages/com.unity.test-framework.performance@3.2/api/Unity.PerformanceTesting.Measurements.MethodMeasurement.html
    // source: Runtime/Measurements/MethodMeasurement.cs (3.1.0, 3.5.0)
    public class MethodMeasurement
    {
        // ...MethodMeasurement.html#Unity_PerformanceTesting_Measurements_MethodMeasurement__ctor_System_Action_
        public MethodMeasurement(Action action) => throw null;

        // ...MethodMeasurement.html#Unity_PerformanceTesting_Measurements_MethodMeasurement_SampleGroup_System_String_
        public MethodMeasurement SampleGroup(string name) => throw null;

        // ...MethodMeasurement.html#Unity_PerformanceTesting_Measurements_MethodMeasurement_SampleGroup_Unity_PerformanceTesting_SampleGroup_
        public MethodMeasurement SampleGroup(Unity.PerformanceTesting.SampleGroup sampleGroup) => throw null;

        // ...MethodMeasurement.html#Unity_PerformanceTesting_Measurements_MethodMeasurement_WarmupCount_System_Int32_
        public MethodMeasurement WarmupCount(int count) => throw null;

        // ...MethodMeasurement.html#Unity_PerformanceTesting_Measurements_MethodMeasurement_IterationsPerMeasurement_System_Int32_
        public MethodMeasurement IterationsPerMeasurement(int count) => throw null;

        // ...MethodMeasurement.html#Unity_PerformanceTesting_Measurements_MethodMeasurement_MeasurementCount_System_Int32_
        public MethodMeasurement MeasurementCount(int count) => throw null;

        // ...MethodMeasurement.html#Unity_PerformanceTesting_Measurements_MethodMeasurement_SetUp_System_Action_
        // (runs before every invocation of the measured action, warm-up included, outside the timed region:
        // ExecuteActionWithCleanupSetup in 3.1.0 and 3.5.0)
        public MethodMeasurement SetUp(Action action) => throw null;

        // ...MethodMeasurement.html#Unity_PerformanceTesting_Measurements_MethodMeasurement_CleanUp_System_Action_
        // (runs after every invocation, outside the timed region; same source)
        public MethodMeasurement CleanUp(Action action) => throw null;

        // ...MethodMeasurement.html#Unity_PerformanceTesting_Measurements_MethodMeasurement_Run
        public void Run() => throw null;
    }
}
