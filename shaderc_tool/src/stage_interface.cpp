// Extraction of a stage's declared globals from glslang's intermediate tree.
#include "stage_interface.hpp"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ShaderLang.h>

namespace prism::shaderc {
namespace {

std::string vectorName(const char* scalar, const char* prefix, int size) {
    if (size <= 1) return scalar;
    return std::string(prefix) + "vec" + std::to_string(size);
}

std::string typeSpelling(const glslang::TType& t) {
    using namespace glslang;
    if (t.isStruct()) return std::string(t.getTypeName().c_str());
    if (t.getBasicType() == EbtSampler) return std::string(t.getSampler().getString().c_str());
    if (t.isMatrix()) {
        std::string base = t.getBasicType() == EbtDouble ? "dmat" : "mat";
        int c = t.getMatrixCols(), r = t.getMatrixRows();
        return c == r ? base + std::to_string(c) : base + std::to_string(c) + "x" + std::to_string(r);
    }
    int n = t.getVectorSize();
    switch (t.getBasicType()) {
        case EbtFloat: return vectorName("float", "", n);
        case EbtDouble: return vectorName("double", "d", n);
        case EbtInt: return vectorName("int", "i", n);
        case EbtUint: return vectorName("uint", "u", n);
        case EbtBool: return vectorName("bool", "b", n);
        default: return std::string(t.getBasicTypeString().c_str());
    }
}

// A struct type's members, each as "type name;" with nested structs spelled out, so two
// struct types of one name but different members compare unequal.
std::string structureOf(const glslang::TType& t) {
    if (!t.isStruct()) return {};
    std::string out;
    for (const auto& member : *t.getStruct()) {
        const glslang::TType& m = *member.type;
        out += typeSpelling(m) + (m.isStruct() ? "{" + structureOf(m) + "}" : "");
        if (m.isArray()) out += "[" + std::to_string(m.isUnsizedArray() ? -1 : m.getOuterArraySize()) + "]";
        out += " " + std::string(m.getFieldName().c_str()) + "; ";
    }
    return out;
}

// A struct type's member types alone, recursively: what makes two blocks that meet at one
// location the same type (SPIR-V types carry no names, so Vulkan matches by members' types).
std::string memberTypesOf(const glslang::TType& t) {
    if (!t.isStruct()) return {};
    std::string out;
    for (const auto& member : *t.getStruct()) {
        const glslang::TType& m = *member.type;
        out += m.isStruct() ? "{" + memberTypesOf(m) + "}" : typeSpelling(m);
        if (m.isArray()) out += "[" + std::to_string(m.isUnsizedArray() ? -1 : m.getOuterArraySize()) + "]";
        out += "; ";
    }
    return out;
}

bool storageKindOf(glslang::TStorageQualifier storage, StorageKind& kind) {
    using namespace glslang;
    switch (storage) {
        case EvqVaryingIn: kind = StorageKind::In; return true;
        case EvqVaryingOut: kind = StorageKind::Out; return true;
        case EvqUniform: kind = StorageKind::Uniform; return true;
        case EvqBuffer: kind = StorageKind::Buffer; return true;
        case EvqPayload: kind = StorageKind::RayPayload; return true;
        case EvqPayloadIn: kind = StorageKind::RayPayloadIn; return true;
        case EvqHitAttr: kind = StorageKind::HitAttribute; return true;
        case EvqCallableData: kind = StorageKind::CallableData; return true;
        case EvqCallableDataIn: kind = StorageKind::CallableDataIn; return true;
        default: return false;
    }
}

class LinkerObjectCollector : public glslang::TIntermTraverser {
  public:
    LinkerObjectCollector(StageInterface& out, EShLanguage language) : out_(out), language_(language) {}

    bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
        if (node->getOp() != glslang::EOpLinkerObjects) return true;
        for (auto* child : node->getSequence())
            if (auto* sym = child->getAsSymbolNode()) add(*sym);
        return false;
    }

  private:
    void add(const glslang::TIntermSymbol& sym) {
        using namespace glslang;
        const TType& type = sym.getType();
        const TQualifier& q = type.getQualifier();
        if (q.builtIn != EbvNone) return;
        std::string name = sym.getName().c_str();
        if (name.rfind("gl_", 0) == 0) return;
        InterfaceVariable v;
        if (!storageKindOf(q.storage, v.storage)) return;
        v.isBlock = type.getBasicType() == EbtBlock;
        v.name = v.isBlock ? std::string(type.getTypeName().c_str()) : name;
        v.type = typeSpelling(type);
        v.structure = structureOf(type);
        v.memberTypes = memberTypesOf(type);
        if (type.isArray()) v.arraySize = type.isUnsizedArray() ? -1 : type.getOuterArraySize();
        v.interpolation = q.flat      ? Interpolation::Flat
                          : q.nopersp ? Interpolation::NoPerspective
                                      : Interpolation::Smooth;
        v.patch = q.patch;
        v.perPrimitive = q.isPerPrimitive();
        if (q.hasLocation()) v.location = static_cast<int>(q.layoutLocation);
        if (q.hasSet()) v.set = static_cast<int>(q.layoutSet);
        if (q.hasBinding()) v.binding = static_cast<int>(q.layoutBinding);
        v.pushConstant = q.isPushConstant();
        // As glslang counts them for its own overlap check (TIntermediate::addUsedLocation).
        if (q.isArrayedIo(language_) && type.isArray()) {
            const TType vertex(type, 0);
            v.locationSlots = TIntermediate::computeTypeLocationSize(vertex, language_);
        } else {
            v.locationSlots = TIntermediate::computeTypeLocationSize(type, language_);
        }
        const TSourceLoc& loc = sym.getLoc();
        v.sourceNumber = static_cast<std::uint32_t>(loc.string < 0 ? 0 : loc.string);
        v.line = loc.line;
        v.column = loc.column;
        out_.variables.push_back(std::move(v));
    }

    StageInterface& out_;
    EShLanguage language_;
};

}  // namespace

StageInterface extractStageInterface(catalog::Stage stage, const glslang::TShader& shader) {
    StageInterface result;
    result.stage = stage;
    const glslang::TIntermediate* im = shader.getIntermediate();
    if (!im || !im->getTreeRoot()) return result;
    LinkerObjectCollector collector(result, shader.getStage());
    im->getTreeRoot()->traverse(&collector);
    return result;
}

std::string glslTypeWithArray(const InterfaceVariable& v) {
    if (v.arraySize == 0) return v.type;
    if (v.arraySize < 0) return v.type + "[]";
    return v.type + "[" + std::to_string(v.arraySize) + "]";
}

std::string_view interpolationName(Interpolation i) {
    switch (i) {
        case Interpolation::Smooth: return "smooth";
        case Interpolation::Flat: return "flat";
        case Interpolation::NoPerspective: return "noperspective";
    }
    return "smooth";
}

}  // namespace prism::shaderc
