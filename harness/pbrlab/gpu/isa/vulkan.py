"""The few Vulkan calls that compile a SPIR-V pipeline and read back what the driver made
of it (``VK_KHR_pipeline_executable_properties``), through ctypes on the system's loader.

Only what :mod:`pbrlab.gpu.isa.device` needs is declared: an instance, one device with the
pipeline-executable feature (and ``shaderFloat16`` where the device has it), shader
modules, descriptor-set and pipeline layouts, a one-subpass render pass,
graphics pipelines, and the statistics and internal representations of their
executables. Structure layouts follow the Vulkan 1.3 headers (vulkan_core.h)."""

from __future__ import annotations

import ctypes
import ctypes.util
from ctypes import (POINTER, Structure, byref, c_char, c_char_p, c_float, c_int32, c_size_t,
                    c_uint32, c_uint64, c_void_p)

from ...foundation.errors import PbrlabError

# ---- constants (vulkan_core.h) ---------------------------------------------------------------
SUCCESS = 0
API_VERSION_1_2 = (1 << 22) | (2 << 12)

ST_APPLICATION_INFO = 0
ST_INSTANCE_CREATE_INFO = 1
ST_DEVICE_QUEUE_CREATE_INFO = 2
ST_DEVICE_CREATE_INFO = 3
ST_SHADER_MODULE_CREATE_INFO = 16
ST_PIPELINE_SHADER_STAGE_CREATE_INFO = 18
ST_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO = 19
ST_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO = 20
ST_PIPELINE_VIEWPORT_STATE_CREATE_INFO = 22
ST_PIPELINE_RASTERIZATION_STATE_CREATE_INFO = 23
ST_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO = 24
ST_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO = 26
ST_PIPELINE_DYNAMIC_STATE_CREATE_INFO = 27
ST_GRAPHICS_PIPELINE_CREATE_INFO = 28
ST_PIPELINE_LAYOUT_CREATE_INFO = 30
ST_DESCRIPTOR_SET_LAYOUT_CREATE_INFO = 32
ST_RENDER_PASS_CREATE_INFO = 38
ST_PHYSICAL_DEVICE_FEATURES_2 = 1000059000
ST_PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES = 1000082000
ST_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR = 1000269000
ST_PIPELINE_INFO_KHR = 1000269001
ST_PIPELINE_EXECUTABLE_PROPERTIES_KHR = 1000269002
ST_PIPELINE_EXECUTABLE_INFO_KHR = 1000269003
ST_PIPELINE_EXECUTABLE_STATISTIC_KHR = 1000269004
ST_PIPELINE_EXECUTABLE_INTERNAL_REPRESENTATION_KHR = 1000269005

PIPELINE_CREATE_CAPTURE_STATISTICS = 0x40
PIPELINE_CREATE_CAPTURE_INTERNAL_REPRESENTATIONS = 0x80

STAGE_VERTEX = 0x1
STAGE_FRAGMENT = 0x10
STAGE_ALL = 0x7FFFFFFF

DESCRIPTOR_SAMPLER = 0
DESCRIPTOR_COMBINED_IMAGE_SAMPLER = 1
DESCRIPTOR_SAMPLED_IMAGE = 2
DESCRIPTOR_STORAGE_IMAGE = 3
DESCRIPTOR_UNIFORM_BUFFER = 6
DESCRIPTOR_STORAGE_BUFFER = 7

FORMAT_R32G32B32A32_SFLOAT = 109
DYNAMIC_STATE_VIEWPORT = 0
DYNAMIC_STATE_SCISSOR = 1

STAT_BOOL32, STAT_INT64, STAT_UINT64, STAT_FLOAT64 = range(4)

Handle = c_uint64  # non-dispatchable handles


class ApplicationInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("pApplicationName", c_char_p),
                ("applicationVersion", c_uint32), ("pEngineName", c_char_p),
                ("engineVersion", c_uint32), ("apiVersion", c_uint32)]


class InstanceCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("pApplicationInfo", POINTER(ApplicationInfo)),
                ("enabledLayerCount", c_uint32), ("ppEnabledLayerNames", POINTER(c_char_p)),
                ("enabledExtensionCount", c_uint32), ("ppEnabledExtensionNames", POINTER(c_char_p))]


class DeviceQueueCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("queueFamilyIndex", c_uint32), ("queueCount", c_uint32),
                ("pQueuePriorities", POINTER(c_float))]


class DeviceCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("queueCreateInfoCount", c_uint32),
                ("pQueueCreateInfos", POINTER(DeviceQueueCreateInfo)),
                ("enabledLayerCount", c_uint32), ("ppEnabledLayerNames", POINTER(c_char_p)),
                ("enabledExtensionCount", c_uint32), ("ppEnabledExtensionNames", POINTER(c_char_p)),
                ("pEnabledFeatures", c_void_p)]


class PipelineExecutableFeatures(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("pipelineExecutableInfo", c_uint32)]


class Float16Int8Features(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("shaderFloat16", c_uint32),
                ("shaderInt8", c_uint32)]


class PhysicalDeviceFeatures2(Structure):
    # VkPhysicalDeviceFeatures is 55 VkBool32
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("features", c_uint32 * 55)]


class ExtensionProperties(Structure):
    _fields_ = [("extensionName", c_char * 256), ("specVersion", c_uint32)]


class ShaderModuleCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("codeSize", c_size_t), ("pCode", c_void_p)]


class DescriptorSetLayoutBinding(Structure):
    _fields_ = [("binding", c_uint32), ("descriptorType", c_uint32),
                ("descriptorCount", c_uint32), ("stageFlags", c_uint32),
                ("pImmutableSamplers", c_void_p)]


class DescriptorSetLayoutCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("bindingCount", c_uint32), ("pBindings", POINTER(DescriptorSetLayoutBinding))]


class PipelineLayoutCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("setLayoutCount", c_uint32), ("pSetLayouts", POINTER(Handle)),
                ("pushConstantRangeCount", c_uint32), ("pPushConstantRanges", c_void_p)]


class PipelineShaderStageCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("stage", c_uint32), ("module", Handle), ("pName", c_char_p),
                ("pSpecializationInfo", c_void_p)]


class VertexInputStateCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("vertexBindingDescriptionCount", c_uint32), ("pVertexBindingDescriptions", c_void_p),
                ("vertexAttributeDescriptionCount", c_uint32),
                ("pVertexAttributeDescriptions", c_void_p)]


class InputAssemblyStateCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("topology", c_uint32), ("primitiveRestartEnable", c_uint32)]


class ViewportStateCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("viewportCount", c_uint32), ("pViewports", c_void_p),
                ("scissorCount", c_uint32), ("pScissors", c_void_p)]


class RasterizationStateCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("depthClampEnable", c_uint32), ("rasterizerDiscardEnable", c_uint32),
                ("polygonMode", c_uint32), ("cullMode", c_uint32), ("frontFace", c_uint32),
                ("depthBiasEnable", c_uint32), ("depthBiasConstantFactor", c_float),
                ("depthBiasClamp", c_float), ("depthBiasSlopeFactor", c_float),
                ("lineWidth", c_float)]


class MultisampleStateCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("rasterizationSamples", c_uint32), ("sampleShadingEnable", c_uint32),
                ("minSampleShading", c_float), ("pSampleMask", c_void_p),
                ("alphaToCoverageEnable", c_uint32), ("alphaToOneEnable", c_uint32)]


class ColorBlendAttachmentState(Structure):
    _fields_ = [("blendEnable", c_uint32), ("srcColorBlendFactor", c_uint32),
                ("dstColorBlendFactor", c_uint32), ("colorBlendOp", c_uint32),
                ("srcAlphaBlendFactor", c_uint32), ("dstAlphaBlendFactor", c_uint32),
                ("alphaBlendOp", c_uint32), ("colorWriteMask", c_uint32)]


class ColorBlendStateCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("logicOpEnable", c_uint32), ("logicOp", c_uint32),
                ("attachmentCount", c_uint32), ("pAttachments", POINTER(ColorBlendAttachmentState)),
                ("blendConstants", c_float * 4)]


class DynamicStateCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("dynamicStateCount", c_uint32), ("pDynamicStates", POINTER(c_uint32))]


class GraphicsPipelineCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("stageCount", c_uint32), ("pStages", POINTER(PipelineShaderStageCreateInfo)),
                ("pVertexInputState", POINTER(VertexInputStateCreateInfo)),
                ("pInputAssemblyState", POINTER(InputAssemblyStateCreateInfo)),
                ("pTessellationState", c_void_p),
                ("pViewportState", POINTER(ViewportStateCreateInfo)),
                ("pRasterizationState", POINTER(RasterizationStateCreateInfo)),
                ("pMultisampleState", POINTER(MultisampleStateCreateInfo)),
                ("pDepthStencilState", c_void_p),
                ("pColorBlendState", POINTER(ColorBlendStateCreateInfo)),
                ("pDynamicState", POINTER(DynamicStateCreateInfo)),
                ("layout", Handle), ("renderPass", Handle), ("subpass", c_uint32),
                ("basePipelineHandle", Handle), ("basePipelineIndex", c_int32)]


class AttachmentDescription(Structure):
    _fields_ = [("flags", c_uint32), ("format", c_uint32), ("samples", c_uint32),
                ("loadOp", c_uint32), ("storeOp", c_uint32), ("stencilLoadOp", c_uint32),
                ("stencilStoreOp", c_uint32), ("initialLayout", c_uint32),
                ("finalLayout", c_uint32)]


class AttachmentReference(Structure):
    _fields_ = [("attachment", c_uint32), ("layout", c_uint32)]


class SubpassDescription(Structure):
    _fields_ = [("flags", c_uint32), ("pipelineBindPoint", c_uint32),
                ("inputAttachmentCount", c_uint32), ("pInputAttachments", c_void_p),
                ("colorAttachmentCount", c_uint32), ("pColorAttachments", POINTER(AttachmentReference)),
                ("pResolveAttachments", c_void_p), ("pDepthStencilAttachment", c_void_p),
                ("preserveAttachmentCount", c_uint32), ("pPreserveAttachments", c_void_p)]


class RenderPassCreateInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("flags", c_uint32),
                ("attachmentCount", c_uint32), ("pAttachments", POINTER(AttachmentDescription)),
                ("subpassCount", c_uint32), ("pSubpasses", POINTER(SubpassDescription)),
                ("dependencyCount", c_uint32), ("pDependencies", c_void_p)]


class PipelineInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("pipeline", Handle)]


class PipelineExecutableProperties(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("stages", c_uint32),
                ("name", c_char * 256), ("description", c_char * 256), ("subgroupSize", c_uint32)]


class PipelineExecutableInfo(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("pipeline", Handle),
                ("executableIndex", c_uint32)]


class StatisticValue(ctypes.Union):
    _fields_ = [("b32", c_uint32), ("i64", ctypes.c_int64), ("u64", c_uint64),
                ("f64", ctypes.c_double)]


class PipelineExecutableStatistic(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("name", c_char * 256),
                ("description", c_char * 256), ("format", c_uint32), ("value", StatisticValue)]


class PipelineExecutableInternalRepresentation(Structure):
    _fields_ = [("sType", c_uint32), ("pNext", c_void_p), ("name", c_char * 256),
                ("description", c_char * 256), ("isText", c_uint32), ("dataSize", c_size_t),
                ("pData", c_void_p)]


class VulkanUnavailable(PbrlabError):
    """No Vulkan loader, or no device of the asked kind."""


def load_loader():
    """The system's Vulkan loader (Debian: libvulkan1)."""
    name = ctypes.util.find_library("vulkan") or "libvulkan.so.1"
    try:
        return ctypes.CDLL(name)
    except OSError as exc:
        raise VulkanUnavailable(
            f"no Vulkan loader ({name}): install the Debian/Ubuntu packages libvulkan1 and "
            "mesa-vulkan-drivers (sudo apt-get install libvulkan1 mesa-vulkan-drivers; in a pbrlab "
            "checkout, scripts/setup.sh does)") from exc


def check(result: int, what: str) -> None:
    if result != SUCCESS:
        raise PbrlabError(f"Vulkan: {what} failed (VkResult {result})")


def text(field: bytes) -> str:
    return field.split(b"\0", 1)[0].decode("utf-8", "replace")


def string_array(names):
    array = (c_char_p * max(1, len(names)))()
    for i, name in enumerate(names):
        array[i] = name.encode()
    return array


__all__ = [name for name in dir() if not name.startswith("_")] + ["byref", "POINTER", "c_uint32",
                                                                  "c_void_p", "c_float", "c_size_t",
                                                                  "c_uint64", "Handle"]
