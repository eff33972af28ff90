// SPDX-License-Identifier: BSD-3-Clause
// The array names of the data contract (shared/DESIGN.md section 2), in one place so that
// every filter, test and script spells them the same way.
#ifndef PolycubeHexArrayNames_h
#define PolycubeHexArrayNames_h

namespace polycubehex
{
namespace ArrayNames
{
// vtkTetrahedralizeFilter
constexpr const char* TetrahedralizeSwitches = "TetrahedralizeSwitches";
// vtkHandleCutFilter
constexpr const char* CutFaces = "CutFaces";
constexpr const char* CutSide = "CutSide";
constexpr const char* CutId = "CutId";
constexpr const char* BettiNumber = "BettiNumber";
constexpr const char* BoundaryGenus = "BoundaryGenus";
constexpr const char* OriginalCellId = "OriginalCellId";
// vtkFrameFieldFilter
constexpr const char* Frame = "Frame";
constexpr const char* FrameU = "FrameU";
constexpr const char* FrameV = "FrameV";
constexpr const char* FrameW = "FrameW";
constexpr const char* CutTransitions = "CutTransitions";
constexpr const char* SingularEdgeCount = "SingularEdgeCount";
constexpr const char* InteriorSingularEdgeCount = "InteriorSingularEdgeCount";
constexpr const char* BoundaryAlignmentError = "BoundaryAlignmentError";
constexpr const char* FrameEnergy = "FrameEnergy";
constexpr const char* FrameIterations = "FrameIterations";
constexpr const char* SingularityType = "SingularityType";
// vtkPolycubeDeformFilter
constexpr const char* OriginalPointId = "OriginalPointId";
constexpr const char* OriginalPoints = "OriginalPoints";
constexpr const char* PolycubeLabels = "PolycubeLabels";
constexpr const char* PolycubeLabel = "PolycubeLabel";
constexpr const char* ChartId = "ChartId";
constexpr const char* PolycubeDefect = "PolycubeDefect";
constexpr const char* CutTranslations = "CutTranslations";
constexpr const char* CornerCount = "CornerCount";
constexpr const char* InvertedTetCount = "InvertedTetCount";
constexpr const char* PolycubeResidual = "PolycubeResidual";
constexpr const char* Guidance = "Guidance";
// vtkHexExtractFilter and vtkHexMeshQuality
constexpr const char* ScaledJacobian = "ScaledJacobian";
constexpr const char* HexCount = "HexCount";
constexpr const char* ScaledJacobianMin = "ScaledJacobianMin";
constexpr const char* ScaledJacobianMean = "ScaledJacobianMean";
constexpr const char* ScaledJacobianHistogram = "ScaledJacobianHistogram";
constexpr const char* InvertedHexCount = "InvertedHexCount";
constexpr const char* DegenerateHexCount = "DegenerateHexCount";
constexpr const char* IrregularBoundaryVertexCount = "IrregularBoundaryVertexCount";
constexpr const char* DistanceMean = "DistanceMean";
constexpr const char* DistanceHausdorff = "DistanceHausdorff";
constexpr const char* IntegerCutTranslations = "IntegerCutTranslations";
constexpr const char* ValidHexMesh = "ValidHexMesh";
constexpr const char* ValidityReport = "ValidityReport";
} // namespace ArrayNames
} // namespace polycubehex

#endif
